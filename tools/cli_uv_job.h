/* tools/cli_uv_job: the frame shared by the commands that read a mesh and
 * write a planar map with its pictures (`scaf param`, `scaf atlas`,
 * `scaf deform`).
 *
 * cli_uv_job_start declares and checks every output (-o, --svg, --png,
 * --report; tools/cli_outputs) before any work, then reads the input mesh
 * (tools/cli_mesh_io) and honours a SIGINT / SIGTERM that arrived
 * meanwhile. cli_uv_job_write_map writes -o; cli_uv_job_png writes the --png picture (app/uv_png) with
 * face colours from a callback. Both print why they failed and return the
 * exit status (tools/exit_codes.h); 0 = go on. */
#ifndef SCAF_TOOLS_CLI_UV_JOB_H
#define SCAF_TOOLS_CLI_UV_JOB_H

#include "app/uv_png.h"
#include "cli_outputs.h"
#include "mesh/mesh.h"
#include "mesh/mesh_io.h"

typedef struct cli_uv_job {
    const char *cmd, *in;
    cli_outputs outs; /* commit or abort them at the end */
    cli_uv_outputs k;
    int png_seams;         /* output index of --png-seams (-1: not asked for) */
    mesh_read_info rinfo;  /* what reading the input said */
    const int *face_group; /* nf: -o gets `g chart_N` groups (NULL: none) */
} cli_uv_job;

/* The paths asked for (NULL: not asked for); extra_input (with its option
 * name, e.g. "--targets") is another file the run reads, protected like
 * the input, or NULL. On 0, *m holds the mesh (the caller frees it);
 * otherwise *m is empty and nothing was written. */
typedef struct cli_uv_job_paths {
    const char *out, *svg, *png, *report;
    const char *extra_input_option, *extra_input;
    const char *png_seams; /* --png-seams (cli_seams), or NULL */
} cli_uv_job_paths;

int cli_uv_job_start(cli_uv_job *j, const char *cmd, const char *in, const cli_uv_job_paths *p,
                     int quiet, mesh *m);

/* -o: the input mesh with its new map (o: the mesh as read with the new
 * UV and FT), written as tools/cli_mesh_io's cli_write_uv: 0 or the exit
 * status. */
int cli_uv_job_write_map(cli_uv_job *j, const mesh *o);

/* The --png picture (when asked for) of the map (nuv positions uv, nf
 * faces F) with face f in colour(f, ctx) (0xRRGGBB), the 3D mesh (nv, V,
 * F3) for the checker: 0 or the exit status. */
int cli_uv_job_png(cli_uv_job *j, int nuv, const double *uv, int nf, const int *F,
                   unsigned (*colour)(int f, const void *ctx), const void *ctx, int nv,
                   const double *V, const int *F3, const uv_png_options *o);

#endif
