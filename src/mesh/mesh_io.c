/* mesh/mesh_io: reading a mesh file (format by extension, gzip transparent).
 *
 * mesh_read loads the whole file into memory (plain files with one read of
 * the known size; gzip files, recognized by their magic bytes, through
 * zlib's gzread into a growing buffer, 1 MiB at a time: each chunk is
 * looked at for a NUL byte in text, which stops a decompression bomb at
 * once, and for a pending SIGINT / SIGTERM), then hands it to mesh_parse, which
 * dispatches to the OBJ, OFF or PLY parser. The format comes from the
 * extension with any ".gz" removed; an unknown extension falls back to
 * looking at the content ("ply" / "...OFF" first token, else OBJ).
 *
 * Failures: SCAF_ERR_IO naming the path when the file cannot be opened or
 * read, SCAF_ERR_PARSE for corrupt gzip data or malformed content
 * ("FILE:LINE: reason"), SCAF_ERR_NOMEM.
 */
#include "mesh/mesh_io.h"

#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>
#include <unistd.h>
#include <zlib.h>

#include "base/interrupt.h"
#include "mesh/mesh_readers.h"

/* Case-insensitive "does s end with suffix". */
static int ends_with(const char *s, size_t n, const char *suffix)
{
    size_t k = strlen(suffix);
    return n >= k && strncasecmp(s + n - k, suffix, k) == 0;
}

mesh_format mesh_format_from_name(const char *path)
{
    size_t n = strlen(path);
    if (ends_with(path, n, ".gz")) n -= 3;
    if (ends_with(path, n, ".obj")) return MESH_FORMAT_OBJ;
    if (ends_with(path, n, ".off")) return MESH_FORMAT_OFF;
    if (ends_with(path, n, ".ply")) return MESH_FORMAT_PLY;
    if (ends_with(path, n, ".gltf") || ends_with(path, n, ".glb")) return MESH_FORMAT_GLTF;
    return MESH_FORMAT_UNKNOWN;
}

mesh_format mesh_format_from_content(const char *data, size_t size)
{
    if (size >= 3 && memcmp(data, "ply", 3) == 0) return MESH_FORMAT_PLY;
    if (size >= 4 && memcmp(data, "glTF", 4) == 0) return MESH_FORMAT_GLTF;
    size_t i = 0;
    if (size >= 3 && memcmp(data, "\xEF\xBB\xBF", 3) == 0) i = 3; /* UTF-8 BOM */
    while (i < size && (data[i] == ' ' || data[i] == '\t' || data[i] == '\r' || data[i] == '\n'))
        i++;
    if (i < size && data[i] == '{') return MESH_FORMAT_GLTF; /* no OBJ/OFF line starts so */
    i = 0;
    while (i < size && (data[i] == ' ' || data[i] == '\t' || data[i] == '\r' || data[i] == '\n'))
        i++;
    size_t j = i;
    while (j < size && j - i < 8 && data[j] > ' ') j++;
    if (j - i >= 3 && memcmp(data + j - 3, "OFF", 3) == 0) return MESH_FORMAT_OFF;
    return MESH_FORMAT_OBJ;
}

scaf_status mesh_parse(const char *data, size_t size, mesh_format format, const char *name, mesh *m,
                       mesh_read_info *info, scaf_error *err)
{
    mesh_read_info scratch;
    if (!info) info = &scratch;
    memset(info, 0, sizeof *info);
    memset(m, 0, sizeof *m);
    if (!name) name = "<memory>";
    if (!data && size) return err_set(err, SCAF_ERR_USAGE, "mesh_parse: NULL data");
    if (!data) data = "";
    /* lines ended by CR alone (classic Mac OS): every parser would see one
     * long first line ("no faces"); say so instead */
    const char *cr = memchr(data, '\r', size);
    if (cr && cr + 1 < data + size && !memchr(data, '\n', size))
        return err_set(err, SCAF_ERR_PARSE,
                       "%s:1: the lines end in CR alone (classic Mac OS line endings); convert "
                       "them to LF or CRLF",
                       name);
    if (format == MESH_FORMAT_UNKNOWN) format = mesh_format_from_content(data, size);
    switch (format) {
    case MESH_FORMAT_OBJ: return mesh_parse_obj(data, size, name, m, info, err);
    case MESH_FORMAT_OFF: return mesh_parse_off(data, size, name, m, info, err);
    case MESH_FORMAT_PLY: return mesh_parse_ply(data, size, name, m, info, err);
    case MESH_FORMAT_GLTF:
        return err_set(err, SCAF_ERR_PARSE, "%s: glTF input is not supported yet", name);
    default: return err_set(err, SCAF_ERR_USAGE, "%s: unknown mesh format", name);
    }
}

/* Read a whole plain file of known size. */
static scaf_status load_plain(int fd, const char *path, size_t size, char **out, size_t *out_size,
                              scaf_error *err)
{
    char *buf = malloc(size ? size : 1);
    if (!buf) return err_set(err, SCAF_ERR_NOMEM, "%s: out of memory (%zu bytes)", path, size);
    size_t got = 0;
    while (got < size) {
        ssize_t r = read(fd, buf + got, size - got > (1u << 30) ? (1u << 30) : size - got);
        if (r < 0 && errno == EINTR) continue;
        if (r < 0) {
            int e = errno;
            free(buf);
            return err_set(err, SCAF_ERR_IO, "%s: cannot read: %s", path, strerror(e));
        }
        if (r == 0) break; /* file shrank while reading: parse what is there */
        got += (size_t)r;
    }
    *out = buf;
    *out_size = got;
    return SCAF_OK;
}

/* Bytes inflated between two looks at them (a signal, a NUL byte). */
#define GZIP_CHUNK ((size_t)1 << 20)
/* A bomb of valid text (one short line repeated) has no NUL byte: it is
 * stopped by its ratio. Mesh files compress 2-10x (text) and less
 * (binary PLY); deflate's best is about 1030x. Past GZIP_RATIO_FROM
 * decompressed bytes, more than GZIP_MAX_RATIO times the compressed size
 * is refused, with the way around it (a plain file has no limit). */
#define GZIP_MAX_RATIO 100
#define GZIP_RATIO_FROM ((size_t)16 << 20)

/* The data decompressed so far is buf[0, n + r), of which [n, n + r) is
 * new. Every text format has no NUL byte in its text: OBJ and OFF
 * throughout, PLY up to "end_header" (binary data may follow). A NUL
 * there stops the decompression at once, so a gzip bomb (gigabytes of
 * zeros) is refused after its first chunk instead of being inflated
 * whole before the parser rejects its first byte. *text_end: where the
 * text ends (SIZE_MAX: not known yet; 0: the rest is binary PLY data). */
static scaf_status text_prefix_check(const char *buf, size_t n, size_t r, const char *path,
                                     size_t *text_end, scaf_error *err)
{
    if (*text_end == 0) return SCAF_OK;
    size_t from = n, to = n + r;
    if (to >= 3 && memcmp(buf, "ply", 3) == 0 && *text_end == SIZE_MAX) {
        /* the header ends at the line "end_header" (searched from a little
         * before the new bytes: it may straddle two chunks) */
        size_t s = from > 16 ? from - 16 : 0;
        for (size_t i = s; i + 10 <= to; i++)
            if (buf[i] == 'e' && memcmp(buf + i, "end_header", 10) == 0) {
                if (i + 10 < to) to = i + 10;
                *text_end = 0; /* what follows may be binary */
                break;
            }
    }
    const char *z = to > from ? memchr(buf + from, '\0', to - from) : NULL;
    if (!z) return SCAF_OK;
    long line = 1;
    for (const char *q = buf; q < z; q++) line += *q == '\n';
    return err_set(err, SCAF_ERR_PARSE,
                   "%s:%ld: a NUL byte in a text mesh file (binary data, not OBJ, OFF or a PLY "
                   "header); stopped decompressing after %zu bytes",
                   path, line, n + r);
}

/* Decompress a whole gzip file (fd is consumed). */
static scaf_status load_gzip(int fd, const char *path, size_t compressed, char **out,
                             size_t *out_size, scaf_error *err)
{
    gzFile gz = gzdopen(fd, "rb");
    if (!gz) {
        close(fd);
        return err_set(err, SCAF_ERR_NOMEM, "%s: cannot start gzip reader", path);
    }
    gzbuffer(gz, 1u << 17);
    size_t cap = compressed < (SIZE_MAX / 8) ? compressed * 4 + 4096 : SIZE_MAX / 2;
    size_t n = 0, text_end = SIZE_MAX; /* SIZE_MAX: the text part's end is not known yet */
    char *buf = malloc(cap);
    scaf_status st = SCAF_OK;
    if (!buf) st = err_set(err, SCAF_ERR_NOMEM, "%s: out of memory", path);
    while (st == SCAF_OK) {
        if (n == cap) {
            if (cap > SIZE_MAX / 2) {
                st = err_set(err, SCAF_ERR_NOMEM, "%s: decompressed data too large", path);
                break;
            }
            char *b = realloc(buf, cap * 2);
            if (!b) {
                st = err_set(err, SCAF_ERR_NOMEM, "%s: out of memory (%zu bytes decompressed)",
                             path, n);
                break;
            }
            buf = b;
            cap *= 2;
        }
        /* a chunk at a time, each looked at before the next is inflated */
        size_t want = cap - n > GZIP_CHUNK ? GZIP_CHUNK : cap - n;
        int r = gzread(gz, buf + n, (unsigned)want);
        if (r < 0) {
            int code;
            const char *msg = gzerror(gz, &code);
            st = code == Z_ERRNO
                ? err_set(err, SCAF_ERR_IO, "%s: cannot read: %s", path, strerror(errno))
                : err_set(err, SCAF_ERR_PARSE, "%s:1: corrupt gzip data (%s)", path, msg);
            break;
        }
        if (r == 0) {
            int code;
            const char *msg = gzerror(gz, &code);
            if (code != Z_OK && code != Z_STREAM_END)
                st = err_set(err, SCAF_ERR_PARSE, "%s:1: corrupt or truncated gzip data (%s)", path,
                             msg);
            break;
        }
        st = text_prefix_check(buf, n, (size_t)r, path, &text_end, err);
        n += (size_t)r;
        if (st == SCAF_OK && n > GZIP_RATIO_FROM && compressed <= SIZE_MAX / GZIP_MAX_RATIO &&
            n > compressed * GZIP_MAX_RATIO)
            st = err_set(err, SCAF_ERR_PARSE,
                         "%s: decompresses to more than %d times its %zu compressed bytes "
                         "(stopped after %zu bytes): a decompression bomb? Mesh files compress "
                         "far less; to read it anyway, decompress it first (gunzip)",
                         path, GZIP_MAX_RATIO, compressed, n);
        if (st == SCAF_OK) st = interrupt_check(NULL, "decompressing the mesh", err);
    }
    gzclose(gz);
    if (st != SCAF_OK) {
        free(buf);
        return st;
    }
    *out = buf;
    *out_size = n;
    return SCAF_OK;
}

scaf_status mesh_load_fd(int fd, const char *name, char **data, size_t *size, scaf_error *err)
{
    *data = NULL;
    *size = 0;
    size_t cap = 1 << 16, n = 0;
    char *buf = malloc(cap);
    if (!buf) return err_set(err, SCAF_ERR_NOMEM, "%s: out of memory", name);
    for (;;) {
        if (n == cap) {
            char *b = cap <= SIZE_MAX / 2 ? realloc(buf, cap * 2) : NULL;
            if (!b) {
                free(buf);
                return err_set(err, SCAF_ERR_NOMEM, "%s: out of memory (%zu bytes read)", name, n);
            }
            buf = b;
            cap *= 2;
        }
        ssize_t r = read(fd, buf + n, cap - n > (1u << 30) ? (1u << 30) : cap - n);
        if (r < 0 && errno == EINTR) {
            if (interrupt_pending()) break; /* reported below */
            continue;
        }
        if (r < 0) {
            int e = errno;
            free(buf);
            return err_set(err, SCAF_ERR_IO, "%s: cannot read: %s", name, strerror(e));
        }
        if (r == 0) break;
        n += (size_t)r;
    }
    scaf_status st = interrupt_check(NULL, "reading the mesh", err);
    if (st == SCAF_OK && n >= 2 && (unsigned char)buf[0] == 0x1f && (unsigned char)buf[1] == 0x8b)
        st = err_set(err, SCAF_ERR_PARSE,
                     "%s:1: gzip-compressed data; only files are decompressed: decompress it "
                     "first (zcat FILE.gz | scaf ...)",
                     name);
    if (st != SCAF_OK) {
        free(buf);
        return st;
    }
    *data = buf;
    *size = n;
    return SCAF_OK;
}

scaf_status mesh_load_file(const char *path, char **data, size_t *size, scaf_error *err)
{
    *data = NULL;
    *size = 0;
    if (!path) return err_set(err, SCAF_ERR_USAGE, "mesh_load_file: no path");
    int fd = open(path, O_RDONLY);
    if (fd < 0) return err_set(err, SCAF_ERR_IO, "%s: cannot open: %s", path, strerror(errno));
    struct stat sb;
    if (fstat(fd, &sb) != 0) {
        int e = errno;
        close(fd);
        return err_set(err, SCAF_ERR_IO, "%s: cannot read: %s", path, strerror(e));
    }
    if (!S_ISREG(sb.st_mode)) {
        close(fd);
        return err_set(err, SCAF_ERR_IO, "%s: cannot read: %s", path,
                       S_ISDIR(sb.st_mode) ? "is a directory" : "not a regular file");
    }
    size_t fsize = (size_t)sb.st_size;
    unsigned char magic[2] = {0, 0};
    ssize_t mr = pread(fd, magic, 2, 0);
    scaf_status st;
    if (mr == 2 && magic[0] == 0x1f && magic[1] == 0x8b) {
        st = load_gzip(fd, path, fsize, data, size, err); /* closes fd */
    } else {
        st = load_plain(fd, path, fsize, data, size, err);
        close(fd);
    }
    return st;
}

scaf_status mesh_read(const char *path, mesh *m, mesh_read_info *info, scaf_error *err)
{
    memset(m, 0, sizeof *m);
    if (info) memset(info, 0, sizeof *info);
    if (!path) return err_set(err, SCAF_ERR_USAGE, "mesh_read: no path");
    char *data = NULL;
    size_t n = 0;
    interrupt_test_point("parse");
    scaf_status st = mesh_load_file(path, &data, &n, err);
    if (st != SCAF_OK) return st;
    st = mesh_parse(data, n, mesh_format_from_name(path), path, m, info, err);
    free(data);
    return st;
}

int mesh_read_warnings(const mesh_read_info *info, char *buf, size_t size)
{
    int n = 0;
    size_t o = 0;
    if (buf && size) buf[0] = '\0';
    if (!info) return 0;
    if (info->polygons_triangulated > 0) {
        n++;
        if (buf && o < size)
            o += (size_t)snprintf(
                buf + o, size - o, "%d polygon%s with more than 3 corners fan-triangulated",
                info->polygons_triangulated, info->polygons_triangulated == 1 ? "" : "s");
    }
    if (info->faces_without_uv > 0) {
        n++;
        if (buf && o < size)
            o += (size_t)snprintf(buf + o, size - o,
                                  "%s%d face%s without texture indices: UVs dropped", o ? "; " : "",
                                  info->faces_without_uv, info->faces_without_uv == 1 ? "" : "s");
    }
    return n;
}
