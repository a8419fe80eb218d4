/* base/atomic_file: temporary file + rename (see atomic_file.h). */
#define _XOPEN_SOURCE 700 /* realpath */
#include "base/atomic_file.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* Symbolic links followed before giving up (the kernel's own limit). */
#define MAX_LINK_HOPS 40

static const char *file_kind(mode_t m)
{
    if (S_ISDIR(m)) return "a directory";
    if (S_ISFIFO(m)) return "a FIFO";
    if (S_ISCHR(m)) return "a character device";
    if (S_ISBLK(m)) return "a block device";
    if (S_ISSOCK(m)) return "a socket";
    return "not a regular file";
}

/* Follow the links of `path` into cur (size bytes): the last name is then
 * a regular file or does not exist yet. */
static scaf_status follow_links(const char *path, char *cur, size_t size, int *exists, mode_t *mode,
                                scaf_error *err)
{
    if (strlen(path) >= size) return err_set(err, SCAF_ERR_IO, "%s: path too long", path);
    strcpy(cur, path);
    *exists = 0;
    for (int hop = 0;; hop++) {
        struct stat st;
        if (lstat(cur, &st) != 0) {
            if (errno == ENOENT) return SCAF_OK; /* a new file (or a missing folder: see below) */
            return err_set(err, SCAF_ERR_IO, "%s: %s", path, strerror(errno));
        }
        if (!S_ISLNK(st.st_mode)) {
            if (!S_ISREG(st.st_mode))
                return err_set(err, SCAF_ERR_IO, "%s is %s, not a regular file: not replaced", path,
                               file_kind(st.st_mode));
            *exists = 1;
            *mode = st.st_mode;
            return SCAF_OK;
        }
        if (hop == MAX_LINK_HOPS)
            return err_set(err, SCAF_ERR_IO, "%s: too many levels of symbolic links", path);
        char link[4096];
        ssize_t n = readlink(cur, link, sizeof link - 1);
        if (n < 0) return err_set(err, SCAF_ERR_IO, "%s: %s", path, strerror(errno));
        link[n] = '\0';
        /* a relative link is relative to the folder holding the link */
        const char *slash = strrchr(cur, '/');
        size_t keep = link[0] == '/' || !slash ? 0 : (size_t)(slash - cur) + 1;
        if (keep + (size_t)n >= size) return err_set(err, SCAF_ERR_IO, "%s: path too long", path);
        memcpy(cur + keep, link, (size_t)n + 1);
    }
}

static scaf_status resolve(const char *path, char *out, size_t size, int *exists, mode_t *mode,
                           scaf_error *err)
{
    if (!path || !*path) return err_set(err, SCAF_ERR_USAGE, "no output path");
    char cur[4096];
    int ex = 0;
    scaf_status st = follow_links(path, cur, sizeof cur, &ex, mode, err);
    if (st != SCAF_OK) return st;
    if (exists) *exists = ex;
    char *slash = strrchr(cur, '/');
    const char *name = slash ? slash + 1 : cur;
    if (!*name || !strcmp(name, ".") || !strcmp(name, ".."))
        return err_set(err, SCAF_ERR_IO, "%s is a directory, not a regular file: not replaced",
                       path);
    const char *dir = ".";
    if (slash == cur) dir = "/";
    else if (slash) {
        *slash = '\0';
        dir = cur;
    }
    char *real = realpath(dir, NULL);
    if (!real)
        return err_set(err, SCAF_ERR_IO, "%s: cannot use the folder '%s': %s", path, dir,
                       strerror(errno));
    int n = snprintf(out, size, "%s/%s", strcmp(real, "/") ? real : "", name);
    free(real);
    if (n < 0 || (size_t)n >= size) return err_set(err, SCAF_ERR_IO, "%s: path too long", path);
    return SCAF_OK;
}

scaf_status atomic_resolve(const char *path, char *out, size_t size, int *exists, scaf_error *err)
{
    mode_t mode = 0;
    return resolve(path, out, size, exists, &mode, err);
}

scaf_status atomic_open(atomic_file *a, const char *path, scaf_error *err)
{
    memset(a, 0, sizeof *a);
    a->name = path;
    int exists = 0;
    mode_t mode = 0;
    scaf_status st = resolve(path, a->path, sizeof a->path - 16, &exists, &mode, err);
    if (st != SCAF_OK) return st;
    /* "<dir>/.<base>.tmpXXXXXX": hidden, in the target's folder */
    const char *slash = strrchr(a->path, '/');
    int dirlen = (int)(slash - a->path) + 1;
    snprintf(a->tmp, sizeof a->tmp, "%.*s.%s.tmpXXXXXX", dirlen, a->path, a->path + dirlen);
    int fd = mkstemp(a->tmp);
    if (fd < 0) {
        int e = errno;
        a->tmp[0] = '\0';
        return err_set(err, SCAF_ERR_IO, "%s: cannot create the file: %s", path, strerror(e));
    }
    /* mkstemp makes it 0600; our outputs are not secret, and a replaced
     * file keeps its permissions */
    (void)fchmod(fd, exists ? (mode & 07777) : 0644);
    a->f = fdopen(fd, "w");
    if (!a->f) {
        int e = errno;
        close(fd);
        remove(a->tmp);
        a->tmp[0] = '\0';
        return err_set(err, SCAF_ERR_IO, "%s: cannot open the file: %s", path, strerror(e));
    }
    return SCAF_OK;
}

scaf_status atomic_finish(atomic_file *a, scaf_error *err)
{
    if (!a->f) return err_set(err, SCAF_ERR_IO, "%s: not open", a->name ? a->name : a->path);
    int bad = ferror(a->f) || fflush(a->f) != 0 || fsync(fileno(a->f)) != 0;
    if (fclose(a->f) != 0) bad = 1;
    a->f = NULL;
    if (bad) {
        remove(a->tmp);
        a->tmp[0] = '\0';
        return err_set(err, SCAF_ERR_IO, "%s: write failed (disk full?)",
                       a->name ? a->name : a->path);
    }
    a->finished = 1;
    return SCAF_OK;
}

scaf_status atomic_rename(atomic_file *a, scaf_error *err)
{
    if (!a->finished || !a->tmp[0])
        return err_set(err, SCAF_ERR_IO, "%s: not written", a->name ? a->name : a->path);
    if (rename(a->tmp, a->path) != 0) {
        int e = errno;
        remove(a->tmp);
        a->tmp[0] = '\0';
        return err_set(err, SCAF_ERR_IO, "%s: cannot rename the temporary file: %s",
                       a->name ? a->name : a->path, strerror(e));
    }
    a->tmp[0] = '\0';
    a->finished = 0;
    return SCAF_OK;
}

scaf_status atomic_commit(atomic_file *a, scaf_error *err)
{
    scaf_status st = atomic_finish(a, err);
    return st != SCAF_OK ? st : atomic_rename(a, err);
}

void atomic_abort(atomic_file *a)
{
    if (a->f) fclose(a->f);
    a->f = NULL;
    if (a->tmp[0]) remove(a->tmp);
    a->tmp[0] = '\0';
    a->finished = 0;
}
