/* tools/cli_uv_job: see cli_uv_job.h. */
#include "cli_uv_job.h"

#include <stdlib.h>

#include "cli_mesh_io.h"
#include "cli_signal.h"
#include "exit_codes.h"

int cli_uv_job_start(cli_uv_job *j, const char *cmd, const char *in, const cli_uv_job_paths *p,
                     int quiet, mesh *m)
{
    j->cmd = cmd;
    j->in = in;
    j->face_group = NULL;
    *m = (mesh){0};
    cli_outputs_init(&j->outs, cmd, in);
    cli_outputs_add_input(&j->outs, p->extra_input_option, p->extra_input);
    j->png_seams = cli_outputs_add(&j->outs, "--png-seams", p->png_seams, CLI_OUTPUT_FILE);
    int rc = cli_outputs_uv(&j->outs, p->out, p->svg, p->png, p->report, &j->k);
    if (rc != EXIT_OK) return rc;
    rc = cli_read_mesh(cmd, in, quiet, m, &j->rinfo);
    if (rc != EXIT_OK) return rc;
    if (cli_signal_report(cmd)) {
        mesh_free(m);
        return EXIT_CANCELLED;
    }
    return EXIT_OK;
}

int cli_uv_job_write_map(cli_uv_job *j, const mesh *o)
{
    scaf_error err;
    err_clear(&err);
    const char *path = cli_outputs_begin(&j->outs, j->k.mesh, &err);
    scaf_status st = path
        ? cli_write_uv_grouped(j->cmd, j->in, &j->rinfo, j->outs.out[j->k.mesh].path, path, o,
                               j->face_group, &err)
        : SCAF_ERR_IO;
    return cli_outputs_end(&j->outs, j->k.mesh, st, &err);
}

int cli_uv_job_png(cli_uv_job *j, int nuv, const double *uv, int nf, const int *F,
                   unsigned (*colour)(int f, const void *ctx), const void *ctx, int nv,
                   const double *V, const int *F3, const uv_png_options *o)
{
    if (j->k.png < 0) return EXIT_OK;
    scaf_error err;
    err_clear(&err);
    unsigned *col = malloc(sizeof(unsigned) * (size_t)(nf > 0 ? nf : 1));
    scaf_status st = col ? SCAF_OK : err_nomem(&err, "picture colours");
    for (int f = 0; col && f < nf; f++) col[f] = colour(f, ctx);
    if (st == SCAF_OK) {
        const char *path = cli_outputs_begin(&j->outs, j->k.png, &err);
        st = path ? uv_png_write(path, nuv, uv, nf, F, col, nv, V, F3, o, &err) : SCAF_ERR_IO;
    }
    free(col);
    return cli_outputs_end(&j->outs, j->k.png, st, &err);
}
