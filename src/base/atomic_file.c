/* base/atomic_file: temporary file + rename (see atomic_file.h). */
#include "base/atomic_file.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

scaf_status atomic_open(atomic_file *a, const char *path, scaf_error *err)
{
    memset(a, 0, sizeof *a);
    if (!path || !*path) return err_set(err, SCAF_ERR_USAGE, "no output path");
    if (strlen(path) + 16 > sizeof a->tmp)
        return err_set(err, SCAF_ERR_IO, "%s: path too long", path);
    strcpy(a->path, path);
    /* "<dir>/.<base>.tmpXXXXXX": hidden, in the target's folder */
    const char *slash = strrchr(path, '/');
    int dirlen = slash ? (int)(slash - path) + 1 : 0;
    snprintf(a->tmp, sizeof a->tmp, "%.*s.%s.tmpXXXXXX", dirlen, path, path + dirlen);
    int fd = mkstemp(a->tmp);
    if (fd < 0) {
        int e = errno;
        a->tmp[0] = '\0';
        return err_set(err, SCAF_ERR_IO, "%s: cannot create the file: %s", path, strerror(e));
    }
    (void)fchmod(fd, 0644); /* mkstemp makes it 0600; our outputs are not secret */
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

scaf_status atomic_commit(atomic_file *a, scaf_error *err)
{
    if (!a->f) return err_set(err, SCAF_ERR_IO, "%s: not open", a->path);
    int bad = ferror(a->f) || fflush(a->f) != 0 || fsync(fileno(a->f)) != 0;
    if (fclose(a->f) != 0) bad = 1;
    a->f = NULL;
    if (bad) {
        remove(a->tmp);
        a->tmp[0] = '\0';
        return err_set(err, SCAF_ERR_IO, "%s: write failed (disk full?)", a->path);
    }
    if (rename(a->tmp, a->path) != 0) {
        int e = errno;
        remove(a->tmp);
        a->tmp[0] = '\0';
        return err_set(err, SCAF_ERR_IO, "%s: cannot rename the temporary file: %s", a->path, strerror(e));
    }
    a->tmp[0] = '\0';
    return SCAF_OK;
}

void atomic_abort(atomic_file *a)
{
    if (a->f) fclose(a->f);
    a->f = NULL;
    if (a->tmp[0]) remove(a->tmp);
    a->tmp[0] = '\0';
}
