/* tools/edit_texture: the --texture image of `scaf edit` (see
 * edit_texture.h). */
#define _POSIX_C_SOURCE 200809L
#include "edit_texture.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "exit_codes.h"

static unsigned long be32(const unsigned char *p)
{
    return (unsigned long)p[0] << 24 | (unsigned long)p[1] << 16 | (unsigned long)p[2] << 8 | p[3];
}

int edit_texture_check(const unsigned char *b, size_t n, int *width, int *height, char *msg,
                       size_t size)
{
    static const unsigned char signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    static const unsigned char iend[12] = {0, 0, 0, 0, 'I', 'E', 'N', 'D', 0xae, 0x42, 0x60, 0x82};
    if (n < 8 || memcmp(b, signature, 8) != 0) {
        snprintf(msg, size, "not a PNG file (no PNG signature in its first 8 bytes)");
        return 0;
    }
    if (n < 8 + 25 || be32(b + 8) != 13 || memcmp(b + 12, "IHDR", 4) != 0) {
        snprintf(msg, size, "a broken PNG file: no IHDR chunk after the signature");
        return 0;
    }
    unsigned long w = be32(b + 16), h = be32(b + 20);
    if (w < 1 || h < 1 || w > EDIT_TEXTURE_MAX_SIDE || h > EDIT_TEXTURE_MAX_SIDE) {
        snprintf(msg, size, "the image is %lu x %lu pixels: each side must be in 1..%d", w, h,
                 EDIT_TEXTURE_MAX_SIDE);
        return 0;
    }
    if (n < 8 + 25 + 12 || memcmp(b + n - 12, iend, 12) != 0) {
        snprintf(msg, size, "a truncated PNG file: it does not end with the IEND chunk");
        return 0;
    }
    *width = (int)w;
    *height = (int)h;
    return 1;
}

int edit_texture_read(const char *path, edit_texture *t, char *msg, size_t size)
{
    memset(t, 0, sizeof *t);
    FILE *f = fopen(path, "rb");
    if (!f) {
        snprintf(msg, size, "--texture %s: cannot open it: %s", path, strerror(errno));
        return EXIT_INPUT;
    }
    struct stat sb;
    if (fstat(fileno(f), &sb) != 0 || !S_ISREG(sb.st_mode)) {
        snprintf(msg, size, "--texture %s: not a regular file", path);
        fclose(f);
        return EXIT_INPUT;
    }
    if ((unsigned long long)sb.st_size > EDIT_TEXTURE_MAX_BYTES) {
        snprintf(msg, size, "--texture %s: %lld bytes, larger than the %lu MiB allowed", path,
                 (long long)sb.st_size, EDIT_TEXTURE_MAX_BYTES >> 20);
        fclose(f);
        return EXIT_INPUT;
    }
    /* one byte more than its size tells a file that grew meanwhile */
    size_t room = (size_t)sb.st_size + 1;
    unsigned char *b = malloc(room);
    if (!b) {
        fclose(f);
        snprintf(msg, size, "--texture %s: out of memory", path);
        return EXIT_NOMEM;
    }
    size_t n = fread(b, 1, room, f);
    int bad = ferror(f);
    fclose(f);
    if (bad || n == room) {
        free(b);
        snprintf(msg, size, "--texture %s: %s", path,
                 bad ? "cannot read it" : "it changed while it was read");
        return EXIT_INPUT;
    }
    char why[256];
    if (!edit_texture_check(b, n, &t->width, &t->height, why, sizeof why)) {
        free(b);
        snprintf(msg, size, "--texture %s: %s", path, why);
        return EXIT_INPUT;
    }
    t->data = b;
    t->len = n;
    return EXIT_OK;
}

void edit_texture_free(edit_texture *t)
{
    free(t->data);
    memset(t, 0, sizeof *t);
}
