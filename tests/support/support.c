/* tests/support: see support.h. */
#include "support/support.h"

#include <stdio.h>
#include <stdlib.h>
#include <sys/stat.h>

#ifndef SCAF_DATA_DIR
#define SCAF_DATA_DIR "../shared/data"
#endif
#ifndef SCAF_TEST_TMPDIR
#define SCAF_TEST_TMPDIR "/tmp"
#endif

const char *test_data_path(const char *relative, char *buf, size_t size)
{
    const char *dir = getenv("SCAF_DATA_DIR");
    if (!dir || !*dir) dir = SCAF_DATA_DIR;
    snprintf(buf, size, "%s/%s", dir, relative);
    struct stat st;
    if (stat(buf, &st) != 0) return NULL;
    return buf;
}

const char *test_tmp_path(const char *name, char *buf, size_t size)
{
    snprintf(buf, size, "%s/%s", SCAF_TEST_TMPDIR, name);
    return buf;
}
