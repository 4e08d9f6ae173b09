/* Command-line helpers of pfmathgen's front end. */
#include "cli.h"

#include <ctype.h>
#include <stdlib.h>
#include <string.h>

int pf_cli_is_identifier(const char *s)
{
    if (!*s || !(isalpha((unsigned char)*s) || *s == '_'))
        return 0;
    for (; *s; s++)
        if (!(isascii((unsigned char)*s) && (isalnum((unsigned char)*s) || *s == '_')))
            return 0;
    return 1;
}

/* The command line as a shell would re-run it: words of [A-Za-z0-9-_./=,:+]
 * as they are, others in single quotes (a quote as '\'').  It is recorded in
 * C block comments, so a "*" followed by "/" is written *''/ (the same word
 * for a shell, and no end of comment).  Lines are spliced before comments
 * end (C17 5.1.1.2 phase 2; the trigraph ??/ is a backslash in phase 1
 * under -std=c17), so "*", a backslash, a newline and "/" in a file name
 * ended the comment as well, and the rest of the name was compiled as code.
 * So a "*" or "/" followed by another of "/", "*" or a backslash gets the
 * '' too ("/" "*" in a comment is -Wcomment's warning, an error under
 * -Werror), and so does "?" "?": no trigraph at all (-Wtrigraphs warns of
 * a ??/ before a newline even in a comment). */
char *pf_cli_command_line(int argc, char **argv)
{
    size_t cap = 16;
    for (int i = 1; i < argc; i++)
        cap += 4 * strlen(argv[i]) + 4;
    char *s = malloc(cap), *q = s;
    if (!s)
        return NULL;
    q += strlen(strcpy(q, "pfmathgen"));
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        int plain = *a != 0;
        for (const char *p = a; *p && plain; p++)
            plain = isascii((unsigned char)*p) && (isalnum((unsigned char)*p) || strchr("-_./=,:+", *p));
        *q++ = ' ';
        if (plain) {
            q += strlen(strcpy(q, a));
            continue;
        }
        *q++ = '\'';
        for (const char *p = a; *p; p++) {
            if (*p == '\'')
                q += strlen(strcpy(q, "'\\''"));
            else if (((p[0] == '*' || p[0] == '/') && p[1] && p[1] != p[0] && strchr("/*\\", p[1])) ||
                     (p[0] == '?' && p[1] == '?'))
                q += strlen(strcpy(q, p[0] == '*' ? "*''" : p[0] == '/' ? "/''" : "?''"));
            else
                *q++ = *p;
        }
        *q++ = '\'';
    }
    *q = 0;
    return s;
}
