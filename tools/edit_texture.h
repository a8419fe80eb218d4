/* tools/edit_texture: the image `scaf edit --texture FILE.png` shows under
 * the UV layout and on the 3D view.
 *
 * Read once at start-up into memory (the server then sends only these
 * bytes, at one fixed path: no file is ever opened for a request). The
 * file must be a PNG: the signature, an IHDR chunk first (width and
 * height in 1..EDIT_TEXTURE_MAX_SIDE), the IEND chunk last (a truncated
 * file is refused), and at most EDIT_TEXTURE_MAX_BYTES long. The browser
 * decodes the pixels; what is checked here is what a page cannot report
 * well: a wrong, truncated or huge file. Fails with the exit status
 * (tools/exit_codes.h: 3 for a missing, unreadable or malformed file)
 * and a message naming the file and what is wrong.
 */
#ifndef SCAF_TOOLS_EDIT_TEXTURE_H
#define SCAF_TOOLS_EDIT_TEXTURE_H

#include <stddef.h>

#define EDIT_TEXTURE_MAX_BYTES (64UL << 20) /* 64 MiB */
#define EDIT_TEXTURE_MAX_SIDE 16384         /* pixels: WebGL's common limit */

typedef struct edit_texture {
    unsigned char *data; /* the file's bytes (NULL: no texture) */
    size_t len;
    int width, height;
} edit_texture;

/* Read and check path into *t. EXIT_OK, or the exit status with msg
 * (size bytes) saying why; *t is then empty. */
int edit_texture_read(const char *path, edit_texture *t, char *msg, size_t size);

/* Check a PNG in memory (the rules above): 1, or 0 with msg. */
int edit_texture_check(const unsigned char *b, size_t n, int *width, int *height, char *msg,
                       size_t size);

void edit_texture_free(edit_texture *t);

#endif
