// geom/tetgen_call: TetGen behind a C interface (see tetgen_call.h). One
// of the project's two C++ files (src/mesh/gltf_io.cpp is the other).
//
// Why a child process: TetGen 1.5.0 reports an error by freeing its mesh
// (terminatetetgen -> freememory) and then `throw int`; unwinding runs
// ~tetgenmesh, which frees the same memory again and crashes before any
// catch is reached. So TetGen runs in a forked child with no handler on
// its stack: an uncaught throw then calls std::terminate WITHOUT unwinding
// (the two-phase unwinder finds no handler), and the child's terminate
// handler reads the thrown code, sends it to the parent and exits. A crash
// of any other kind kills only the child. The result travels back through
// a pipe; the parent never runs TetGen and keeps no global state.
#define TETLIBRARY
#include <tetgen.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <new>
#include <sys/wait.h>
#include <unistd.h>

#include "geom/tetgen_call.h"

namespace
{

const char *reason(int code)
{
    switch (code) {
    case 1: return "out of memory";
    case 2: return "internal error in TetGen";
    case 3: return "input facets intersect each other (self-intersecting surface)";
    case 4: return "an input feature is smaller than TetGen's tolerance (nearly coincident points)";
    case 5: return "two input facets are too close to each other";
    case 10:
        return "invalid input (e.g. an open or non-manifold surface, a facet with repeated points)";
    default: return "unknown TetGen error";
    }
}

// What the child sends first: ok, or TetGen's error code; then the sizes.
struct reply_header {
    int ok;
    int code;
    int np, nt, nattributes;
};

bool write_all(int fd, const void *p, size_t n)
{
    const char *c = static_cast<const char *>(p);
    while (n > 0) {
        ssize_t w = write(fd, c, n);
        if (w < 0 && errno == EINTR) continue;
        if (w <= 0) return false;
        c += w;
        n -= (size_t)w;
    }
    return true;
}

bool read_all(int fd, void *p, size_t n)
{
    char *c = static_cast<char *>(p);
    while (n > 0) {
        ssize_t r = read(fd, c, n);
        if (r < 0 && errno == EINTR) continue;
        if (r <= 0) return false;
        c += r;
        n -= (size_t)r;
    }
    return true;
}

// ---- the child ----

int child_fd = -1; // only ever set in the forked child

[[noreturn]] void child_terminate()
{
    reply_header h = {0, 2, 0, 0, 0};
    try {
        throw;
    } catch (int code) {
        h.code = code;
    } catch (const std::bad_alloc &) {
        h.code = 1;
    } catch (...) {
        h.code = 2;
    }
    write_all(child_fd, &h, sizeof h);
    _exit(1);
}

// tetgenio frees its lists with delete[]: fill them with new[].
void fill_input(tetgenio &in, int np, const double *P, int ntri, const int *tri, int nseed,
                const double *seed)
{
    in.firstnumber = 0;
    in.numberofpoints = np;
    in.pointlist = new REAL[3 * (size_t)np];
    std::memcpy(in.pointlist, P, sizeof(double) * 3 * (size_t)np);
    in.numberoffacets = ntri;
    in.facetlist = new tetgenio::facet[(size_t)ntri];
    for (int f = 0; f < ntri; f++) {
        tetgenio::facet &fc = in.facetlist[f];
        tetgenio::init(&fc);
        fc.numberofpolygons = 1;
        fc.polygonlist = new tetgenio::polygon[1];
        tetgenio::init(&fc.polygonlist[0]);
        fc.polygonlist[0].numberofvertices = 3;
        fc.polygonlist[0].vertexlist = new int[3];
        for (int k = 0; k < 3; k++) fc.polygonlist[0].vertexlist[k] = tri[3 * (size_t)f + k];
    }
    in.numberofregions = nseed;
    if (nseed > 0) {
        // x, y, z, attribute, volume constraint (unused)
        in.regionlist = new REAL[5 * (size_t)nseed];
        for (int s = 0; s < nseed; s++) {
            for (int k = 0; k < 4; k++) in.regionlist[5 * (size_t)s + k] = seed[4 * (size_t)s + k];
            in.regionlist[5 * (size_t)s + 4] = -1;
        }
    }
}

// No try/catch here or in the caller: see the file comment.
[[noreturn]] void child_run(int fd, int np, const double *P, int ntri, const int *tri, int nseed,
                            const double *seed)
{
    child_fd = fd;
    std::set_terminate(child_terminate);
    tetgenio in, out;
    fill_input(in, np, P, ntri, tri, nseed, seed);
    tetgenbehavior b;
    char switches[] = "pYMAzQ";
    if (!b.parse_commandline(switches)) throw 2;
    tetrahedralize(&b, &in, &out);
    if (out.numberofcorners != 4) throw 2;
    reply_header h = {1, 0, out.numberofpoints, out.numberoftetrahedra,
                      out.numberoftetrahedronattributes};
    bool ok = write_all(fd, &h, sizeof h) &&
        write_all(fd, out.pointlist, sizeof(double) * 3 * (size_t)h.np) &&
        write_all(fd, out.tetrahedronlist, sizeof(int) * 4 * (size_t)h.nt);
    for (int t = 0; ok && t < h.nt && h.nattributes > 0; t++)
        ok =
            write_all(fd, &out.tetrahedronattributelist[(size_t)h.nattributes * t], sizeof(double));
    _exit(ok ? 0 : 1);
}

// ---- the parent ----

scaf_status read_reply(int fd, tetgen_result *r, scaf_error *err)
{
    reply_header h;
    if (!read_all(fd, &h, sizeof h)) return SCAF_ERR_INTERNAL; // the child died: said by the caller
    if (!h.ok)
        return err_set(err,
                       h.code == 1       ? SCAF_ERR_NOMEM
                           : h.code == 2 ? SCAF_ERR_INTERNAL
                                         : SCAF_ERR_MESH,
                       "TetGen cannot mesh the surface: %s (TetGen error %d)", reason(h.code),
                       h.code);
    if (h.np < 0 || h.nt < 0)
        return err_set(err, SCAF_ERR_INTERNAL, "TetGen returned negative sizes");
    r->np = h.np;
    r->nt = h.nt;
    r->P = (double *)std::malloc(sizeof(double) * 3 * (size_t)(h.np > 0 ? h.np : 1));
    r->T = (int *)std::malloc(sizeof(int) * 4 * (size_t)(h.nt > 0 ? h.nt : 1));
    r->attribute = (double *)std::calloc((size_t)(h.nt > 0 ? h.nt : 1), sizeof(double));
    if (!r->P || !r->T || !r->attribute) return err_nomem(err, "the TetGen mesh");
    if (!read_all(fd, r->P, sizeof(double) * 3 * (size_t)h.np) ||
        !read_all(fd, r->T, sizeof(int) * 4 * (size_t)h.nt) ||
        (h.nattributes > 0 && !read_all(fd, r->attribute, sizeof(double) * (size_t)h.nt)))
        return err_set(err, SCAF_ERR_INTERNAL, "the TetGen process ended before sending its mesh");
    return SCAF_OK;
}

} // namespace

extern "C" void tetgen_result_free(tetgen_result *r)
{
    std::free(r->P);
    std::free(r->T);
    std::free(r->attribute);
    std::memset(r, 0, sizeof *r);
}

extern "C" scaf_status tetgen_call(int np, const double *P, int ntri, const int *tri, int nseed,
                                   const double *seed, tetgen_result *out, scaf_error *err)
{
    std::memset(out, 0, sizeof *out);
    if (np < 4 || ntri < 4 || nseed < 0 || !P || !tri || (nseed > 0 && !seed))
        return err_set(err, SCAF_ERR_USAGE, "tetgen_call: bad arguments (%d points, %d facets)", np,
                       ntri);
    int fds[2];
    if (pipe(fds) != 0)
        return err_set(err, SCAF_ERR_INTERNAL, "cannot create a pipe for TetGen: %s",
                       std::strerror(errno));
    pid_t pid = fork();
    if (pid < 0) {
        close(fds[0]);
        close(fds[1]);
        return err_set(err, SCAF_ERR_NOMEM, "cannot start the TetGen process: %s",
                       std::strerror(errno));
    }
    if (pid == 0) {
        close(fds[0]);
        child_run(fds[1], np, P, ntri, tri, nseed, seed);
    }
    close(fds[1]);
    scaf_error child_err;
    err_clear(&child_err);
    scaf_status s = read_reply(fds[0], out, &child_err);
    close(fds[0]);
    int wstatus = 0;
    while (waitpid(pid, &wstatus, 0) < 0 && errno == EINTR) {}
    if (s != SCAF_OK && child_err.message[0] == '\0') {
        if (WIFSIGNALED(wstatus))
            s = err_set(err, SCAF_ERR_INTERNAL, "TetGen crashed (signal %d) on this input",
                        WTERMSIG(wstatus));
        else
            s = err_set(err, SCAF_ERR_INTERNAL, "TetGen ended without a mesh (exit status %d)",
                        WIFEXITED(wstatus) ? WEXITSTATUS(wstatus) : -1);
    } else if (s != SCAF_OK) {
        err_set(err, s, "%s", child_err.message);
    }
    if (s != SCAF_OK) tetgen_result_free(out);
    return s;
}
