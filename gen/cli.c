/* Command-line helpers shared by pfmathgen's float and fixed-point front ends. */
#include "cli.h"

#include <ctype.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

void pf_cli_die2(const char *fmt, const char *a, const char *b)
{
    fprintf(stderr, "pfmathgen: ");
    fprintf(stderr, fmt, a, b);
    fputc('\n', stderr);
    exit(2);
}

int pf_cli_is_identifier(const char *s)
{
    if (!*s || !(isalpha((unsigned char)*s) || *s == '_'))
        return 0;
    for (; *s; s++)
        if (!(isalnum((unsigned char)*s) || *s == '_'))
            return 0;
    return 1;
}

/* The command line as a shell would re-run it (quoted where needed). */
char *pf_cli_command_line(int argc, char **argv)
{
    size_t cap = 64;
    for (int i = 1; i < argc; i++)
        cap += 4 * strlen(argv[i]) + 4;
    char *s = malloc(cap);
    if (!s)
        exit(1);
    strcpy(s, "pfmathgen");
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        int plain = *a != 0;
        for (const char *p = a; *p; p++)
            if (!(isalnum((unsigned char)*p) || strchr("-_./=,:+", *p)))
                plain = 0;
        strcat(s, " ");
        if (plain) {
            strcat(s, a);
        } else {
            strcat(s, "'");
            for (const char *p = a; *p; p++) {
                if (*p == '\'')
                    strcat(s, "'\\''");
                else
                    strncat(s, p, 1);
            }
            strcat(s, "'");
        }
    }
    return s;
}

int pf_cli_write_atomically(const char *path, const char *data, size_t n)
{
    size_t len = strlen(path) + 32;
    char *tmp = malloc(len);
    if (!tmp)
        return -1;
    snprintf(tmp, len, "%s.tmp.%ld", path, (long)getpid());
    FILE *f = fopen(tmp, "w");
    int ok = f && fwrite(data, 1, n, f) == n;
    if (f && fclose(f) != 0)
        ok = 0;
    if (ok && rename(tmp, path) != 0)
        ok = 0;
    if (!ok)
        unlink(tmp);
    free(tmp);
    return ok ? 0 : -1;
}
