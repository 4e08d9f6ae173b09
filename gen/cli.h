/* Command-line helpers shared by pfmathgen's front ends (gen/pfmathgen.c,
 * gen/fixedgen.c): one error convention, one way to record the command. */
#ifndef PF_CLI_H
#define PF_CLI_H
#include <stddef.h>

/* "pfmathgen: " + fmt(a, b) on stderr, one line, exit status 2 */
__attribute__((noreturn)) void pf_cli_die2(const char *fmt, const char *a, const char *b);
int pf_cli_is_identifier(const char *s);
/* the command line as a shell would re-run it (quoted where needed); malloc'd */
char *pf_cli_command_line(int argc, char **argv);
/* write to PATH.tmp.PID, then rename: no partial file on failure */
int pf_cli_write_atomically(const char *path, const char *data, size_t n);

#endif
