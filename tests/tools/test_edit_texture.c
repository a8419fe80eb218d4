/* tools/edit_texture: the --texture image of `scaf edit`. A PNG is taken
 * (its size read from IHDR); a file that is not one, a truncated one, one
 * with a side of 0 or over the limit, a missing file, a folder and a file
 * over the byte limit are refused with a message saying which, exit
 * status 3. */
#define _POSIX_C_SOURCE 200809L
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include <cmocka.h>

#include "edit_texture.h"
#include "exit_codes.h"
#include "support/support.h"

/* A PNG's frame: signature, IHDR of w x h, IEND (no pixel data: the
 * browser decodes those, not edit_texture). */
static size_t frame(unsigned char *b, unsigned long w, unsigned long h)
{
    static const unsigned char head[] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n',
                                         0,    0,   0,   13,  'I',  'H',  'D',  'R'};
    static const unsigned char iend[] = {0, 0, 0, 0, 'I', 'E', 'N', 'D', 0xae, 0x42, 0x60, 0x82};
    size_t n = 0;
    memcpy(b, head, sizeof head);
    n += sizeof head;
    for (int k = 3; k >= 0; k--) b[n++] = (unsigned char)(w >> (8 * k));
    for (int k = 3; k >= 0; k--) b[n++] = (unsigned char)(h >> (8 * k));
    memcpy(b + n, "\x08\x02\x00\x00\x00\x01\x02\x03\x04", 9); /* depth .. crc */
    n += 9;
    memcpy(b + n, iend, sizeof iend);
    return n + sizeof iend;
}

static void checks_the_frame(void **state)
{
    (void)state;
    unsigned char b[128];
    char msg[256];
    int w = 0, h = 0;
    size_t n = frame(b, 640, 480);
    assert_true(edit_texture_check(b, n, &w, &h, msg, sizeof msg));
    assert_int_equal(w, 640);
    assert_int_equal(h, 480);
    b[1] = 'Q';
    assert_false(edit_texture_check(b, n, &w, &h, msg, sizeof msg));
    assert_non_null(strstr(msg, "not a PNG"));
    n = frame(b, 640, 480);
    assert_false(edit_texture_check(b, n - 5, &w, &h, msg, sizeof msg));
    assert_non_null(strstr(msg, "truncated"));
    n = frame(b, 0, 480);
    assert_false(edit_texture_check(b, n, &w, &h, msg, sizeof msg));
    assert_non_null(strstr(msg, "0 x 480 pixels"));
    n = frame(b, 16385, 2);
    assert_false(edit_texture_check(b, n, &w, &h, msg, sizeof msg));
    assert_non_null(strstr(msg, "16385 x 2"));
    memcpy(b + 12, "IDAT", 4);
    assert_false(edit_texture_check(b, n, &w, &h, msg, sizeof msg));
    assert_non_null(strstr(msg, "IHDR"));
    assert_false(edit_texture_check(b, 5, &w, &h, msg, sizeof msg));
}

static void reads_files(void **state)
{
    (void)state;
    char path[512], msg[1024];
    edit_texture t;
    test_tmp_path("edit_texture.png", path, sizeof path);
    unsigned char b[128];
    size_t n = frame(b, 3, 5);
    FILE *f = fopen(path, "wb");
    assert_non_null(f);
    assert_int_equal(fwrite(b, 1, n, f), n);
    fclose(f);
    assert_int_equal(edit_texture_read(path, &t, msg, sizeof msg), EXIT_OK);
    assert_int_equal(t.len, n);
    assert_memory_equal(t.data, b, n);
    assert_int_equal(t.width, 3);
    assert_int_equal(t.height, 5);
    edit_texture_free(&t);
    assert_null(t.data);
    /* over the byte limit (a sparse file: no disk used) */
    assert_int_equal(truncate(path, (off_t)EDIT_TEXTURE_MAX_BYTES + 1), 0);
    assert_int_equal(edit_texture_read(path, &t, msg, sizeof msg), EXIT_INPUT);
    assert_non_null(strstr(msg, "larger than the 64 MiB"));
    assert_null(t.data);
    remove(path);
    assert_int_equal(edit_texture_read(path, &t, msg, sizeof msg), EXIT_INPUT);
    assert_non_null(strstr(msg, "cannot open it"));
    assert_non_null(strstr(msg, "edit_texture.png"));
    char dir[512];
    test_tmp_path("", dir, sizeof dir);
    assert_int_equal(edit_texture_read(dir, &t, msg, sizeof msg), EXIT_INPUT);
    assert_non_null(strstr(msg, "not a regular file"));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(checks_the_frame),
        cmocka_unit_test(reads_files),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
