/* Command-line helpers of pfmathgen's front end (gen/front/request.c). */
#ifndef PF_CLI_H
#define PF_CLI_H
#include <stddef.h>

int pf_cli_is_identifier(const char *s);
/* the command line as a shell would re-run it (quoted where needed), safe
 * inside a C block comment; malloc'd (NULL when out of memory) */
char *pf_cli_command_line(int argc, char **argv);

#endif
