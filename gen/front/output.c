/* Safe output: see output.h.  Nothing here deletes or replaces a file the
 * program did not create, except a regular file (or a symlink's regular
 * target) that is the named output, and that only by an atomic rename. */
#include "output.h"

#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#define MAX_LINKS 40 /* as the kernel's own limit on nested symlinks */

char *pf_out_dirname(const char *path)
{
    const char *s = strrchr(path, '/');
    if (!s)
        return strdup(".");
    while (s > path && s[-1] == '/')
        s--;
    if (s == path)
        return strdup("/");
    return strndup(path, (size_t)(s - path));
}

/* Follows symlinks at the last component: the file a write would reach.
 * Returns malloc'd path, or NULL with a reason. */
static char *resolve(const char *path, char *err, size_t errlen)
{
    char *p = strdup(path);
    for (int hop = 0; p; hop++) {
        struct stat sb;
        if (lstat(p, &sb) != 0) {
            if (errno == ENOENT)
                return p;
            snprintf(err, errlen, "%s: %s", p, strerror(errno));
            free(p);
            return NULL;
        }
        if (!S_ISLNK(sb.st_mode))
            return p;
        if (hop == MAX_LINKS) {
            snprintf(err, errlen, "%s: too many levels of symbolic links", path);
            free(p);
            return NULL;
        }
        char t[PATH_MAX];
        ssize_t k = readlink(p, t, sizeof t - 1);
        if (k < 0) {
            snprintf(err, errlen, "%s: %s", p, strerror(errno));
            free(p);
            return NULL;
        }
        t[k] = 0;
        char *next;
        if (t[0] == '/') {
            next = strdup(t);
        } else {
            char *d = pf_out_dirname(p);
            size_t len = strlen(d) + strlen(t) + 2;
            next = d ? malloc(len) : NULL;
            if (next)
                snprintf(next, len, "%s/%s", d, t);
            free(d);
        }
        free(p);
        p = next;
    }
    snprintf(err, errlen, "out of memory");
    return NULL;
}

/* the checks shared by pf_out_check and pf_out_stage; *special set for a
 * device/FIFO; returns the resolved target or NULL */
static char *check_target(const char *what, const char *path, int *special, char *err, size_t errlen)
{
    *special = 0;
    if (!*path) {
        snprintf(err, errlen, "%s: empty file name", what);
        return NULL;
    }
    /* a pipe reached through /proc/self/fd (-o /dev/stdout |
       less): that link reads "pipe:[N]", no name for resolve to follow
       (it failed with ENOENT after the fit), but the kernel opens it, so
       the name given is written in place like any special file */
    struct stat sp;
    if (stat(path, &sp) == 0 && S_ISFIFO(sp.st_mode)) {
        if (access(path, W_OK) != 0) {
            snprintf(err, errlen, "%s %s: cannot write (%s)", what, path, strerror(errno));
            return NULL;
        }
        *special = 1;
        char *p = strdup(path);
        if (!p)
            snprintf(err, errlen, "out of memory");
        return p;
    }
    char e2[PATH_MAX + 64];
    char *r = resolve(path, e2, sizeof e2);
    if (!r) {
        snprintf(err, errlen, "%s %s", what, e2);
        return NULL;
    }
    struct stat sb;
    uid_t owner = (uid_t)-1; /* an existing regular file's owner */
    if (stat(r, &sb) == 0) {
        if (S_ISREG(sb.st_mode))
            owner = sb.st_uid;
        if (S_ISDIR(sb.st_mode)) {
            snprintf(err, errlen, "%s %s: is a directory (give a file name)", what, path);
            free(r);
            return NULL;
        }
        if (!S_ISREG(sb.st_mode)) {
            if (access(r, W_OK) != 0) {
                snprintf(err, errlen, "%s %s: cannot write (%s)", what, path, strerror(errno));
                free(r);
                return NULL;
            }
            *special = 1;
            return r;
        }
        /* a read-only file stays as it is, as for "> file": the rename
           beside it needs only the directory's permission */
        if (access(r, W_OK) != 0) {
            snprintf(err, errlen, "%s %s: cannot write (%s)", what, path, strerror(errno));
            free(r);
            return NULL;
        }
    } else if (errno != ENOENT) {
        snprintf(err, errlen, "%s %s: %s", what, path, strerror(errno));
        free(r);
        return NULL;
    }
    char *d = pf_out_dirname(r);
    if (!d) {
        free(r);
        snprintf(err, errlen, "out of memory");
        return NULL;
    }
    const char *why = NULL;
    if (stat(d, &sb) != 0)
        why = "does not exist";
    else if (!S_ISDIR(sb.st_mode))
        why = "is not a directory";
    else if (access(d, W_OK | X_OK) != 0)
        why = "is not writable";
    /* another user's file in a sticky directory (/tmp) may be written but
       not renamed over (EPERM, after the fit): refused now, as the rename
       is the only way this file is replaced (root may, as CAP_FOWNER) */
    else if (owner != (uid_t)-1 && (sb.st_mode & S_ISVTX) && geteuid() != 0 && owner != geteuid() &&
             sb.st_uid != geteuid())
        why = "is sticky and the file is another user's: it cannot be replaced (remove it, or give another name)";
    if (why) {
        snprintf(err, errlen, "%s %s: the directory %s %s", what, path, d, why);
        free(d);
        free(r);
        return NULL;
    }
    free(d);
    return r;
}

int pf_out_check(const char *what, const char *path, char *err, size_t errlen)
{
    int special;
    char *r = check_target(what, path, &special, err, errlen);
    free(r);
    return r ? 0 : -1;
}

/* the file a write to path would reach, spelled canonically: symlinks
 * followed (resolve), the directory through realpath; malloc'd or NULL */
static char *canonical(const char *path)
{
    char e[PATH_MAX + 64];
    char *r = resolve(path, e, sizeof e);
    if (!r)
        return NULL;
    char *d = pf_out_dirname(r), *rd = d ? realpath(d, NULL) : NULL;
    const char *base = strrchr(r, '/') ? strrchr(r, '/') + 1 : r;
    size_t len = rd ? strlen(rd) + strlen(base) + 2 : 0;
    char *c = rd ? malloc(len) : NULL;
    if (c)
        snprintf(c, len, "%s/%s", rd, base);
    free(d);
    free(rd);
    free(r);
    return c;
}

int pf_out_same(const char *a, const char *b)
{
    struct stat sa, sb;
    if (stat(a, &sa) == 0 && stat(b, &sb) == 0 && sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino)
        return 1; /* one file (also by a hard link) */
    char *ca = canonical(a), *cb = canonical(b);
    int same = ca && cb ? !strcmp(ca, cb) : !strcmp(a, b);
    free(ca);
    free(cb);
    return same;
}

static int write_all(int fd, const char *data, size_t n)
{
    while (n) {
        ssize_t k = write(fd, data, n);
        if (k < 0 && errno == EINTR)
            continue;
        if (k <= 0)
            return -1;
        data += k;
        n -= (size_t)k;
    }
    return 0;
}

int pf_out_stage(const char *path, const char *data, size_t n, pf_out_staged *s, char *err, size_t errlen)
{
    memset(s, 0, sizeof *s);
    int special;
    char *r = check_target("cannot write", path, &special, err, errlen);
    if (!r)
        return -1;
    s->target = r;
    s->data = data;
    s->n = n;
    if (special)
        return 0;
    /* ".NAME.XXXXXX" beside the target: the same file system, so rename is
       atomic.  NAME is the target's name cut to 64 bytes: a name of up to
       NAME_MAX bytes is a good target, but 8 more made the temporary's
       ENAMETOOLONG, after the whole fit (pf_out_check had passed it). */
    char *d = pf_out_dirname(r);
    const char *base = strrchr(r, '/') ? strrchr(r, '/') + 1 : r;
    int blen = strlen(base) > 64 ? 64 : (int)strlen(base);
    size_t len = (d ? strlen(d) : 0) + (size_t)blen + 16;
    s->tmp = d ? malloc(len) : NULL;
    if (!s->tmp) {
        free(d);
        pf_out_abort(s);
        snprintf(err, errlen, "out of memory");
        return -1;
    }
    snprintf(s->tmp, len, "%s/.%.*s.XXXXXX", d, blen, base);
    free(d);
    int fd = mkstemp(s->tmp);
    if (fd < 0) {
        snprintf(err, errlen, "cannot write %s: %s", path, strerror(errno));
        free(s->tmp);
        s->tmp = NULL;
        pf_out_abort(s);
        return -1;
    }
    /* the mode a new file would get (mkstemp makes 0600), or the old file's */
    struct stat sb;
    mode_t mask = umask(0);
    umask(mask);
    mode_t mode = stat(r, &sb) == 0 ? (sb.st_mode & 07777) : (0666 & ~mask);
    int ok = fchmod(fd, mode) == 0 && write_all(fd, data, n) == 0;
    int e = errno;
    if (close(fd) != 0 && ok) {
        ok = 0;
        e = errno;
    }
    if (!ok) {
        snprintf(err, errlen, "cannot write %s: %s", path, strerror(e));
        pf_out_abort(s);
        return -1;
    }
    return 0;
}

int pf_out_commit(pf_out_staged *s, char *err, size_t errlen)
{
    int rc = 0;
    if (s->tmp) {
        if (rename(s->tmp, s->target) != 0) {
            snprintf(err, errlen, "cannot write %s: %s", s->target, strerror(errno));
            rc = -1;
        } else {
            free(s->tmp);
            s->tmp = NULL;
        }
    } else if (s->target) {
        /* a device or FIFO: written in place, never created or truncated */
        int fd = open(s->target, O_WRONLY | O_NOCTTY | O_CLOEXEC);
        if (fd < 0 || write_all(fd, s->data, s->n) != 0) {
            snprintf(err, errlen, "cannot write %s: %s", s->target, strerror(errno));
            rc = -1;
        }
        if (fd >= 0)
            close(fd);
    }
    pf_out_abort(s);
    return rc;
}

int pf_out_commit_all(pf_out_staged *s, int n, char *err, size_t errlen)
{
    int rc = 0;
    /* pass 0: the special files (tmp NULL), pass 1: the renames */
    for (int pass = 0; pass < 2; pass++)
        for (int i = 0; i < n && !rc; i++)
            if (s[i].target && !s[i].tmp == !pass)
                rc = pf_out_commit(&s[i], err, errlen);
    for (int i = 0; i < n; i++)
        pf_out_abort(&s[i]);
    return rc;
}

void pf_out_abort(pf_out_staged *s)
{
    if (s->tmp)
        unlink(s->tmp);
    free(s->tmp);
    free(s->target);
    memset(s, 0, sizeof *s);
}

int pf_out_write(const char *path, const char *data, size_t n, char *err, size_t errlen)
{
    pf_out_staged s;
    if (pf_out_stage(path, data, n, &s, err, errlen) != 0)
        return -1;
    return pf_out_commit(&s, err, errlen);
}
