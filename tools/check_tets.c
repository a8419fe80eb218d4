/* tools/check_tets: see check_tets.h; the check is the public
 * scaf_check_tets. */
#include "check_tets.h"

#include <stdio.h>
#include <string.h>

#include "base/json_write.h"
#include "exit_codes.h"
#include "mesh/tet_medit.h"
#include "scaf/volume.h"

int check_tets_applies(const char *path)
{
    size_t n = strlen(path);
    return n > 5 && !strcmp(path + n - 5, ".mesh");
}

int check_tets_run(const char *path, int json)
{
    scaf_error err;
    err_clear(&err);
    tet_medit m;
    scaf_tets_report_t r = {.struct_size = sizeof r};
    scaf_status s = tet_medit_read(path, &m, &err);
    if (s == SCAF_OK) {
        s = scaf_check_tets(m.V, m.nv, m.T, m.nt, &r);
        tet_medit_free(&m);
        if (s != SCAF_OK) snprintf(err.message, sizeof err.message, "%s: %s", path, r.message);
    }
    if (s != SCAF_OK) {
        fprintf(stderr, "scaf check: %s\n", err.message);
        return exit_code_for(s);
    }
    if (json) {
        json_write_report_head(stdout, "check");
        printf(",\n  \"input\": ");
        json_write_string(stdout, path);
        printf(",\n  \"check\": \"tet_orientation\", \"tets\": %d, \"positive\": %d, \"inverted\": "
               "%d, "
               "\"degenerate\": %d, \"first_bad\": %d, \"valid\": %s}\n",
               r.tets, r.positive, r.inverted, r.degenerate, r.first_bad,
               r.valid ? "true" : "false");
    } else {
        printf("%s: %s\n", path,
               r.valid ? "every tet positively oriented" : "INVERTED OR FLAT TETS");
        printf("  tets                 %d\n", r.tets);
        printf("  positive             %d\n", r.positive);
        printf("  inverted             %d\n", r.inverted);
        printf("  degenerate (flat)    %d\n", r.degenerate);
        if (r.first_bad >= 0) printf("  first bad tet        %d (0-based)\n", r.first_bad);
    }
    return r.valid ? EXIT_OK : EXIT_NOT_BIJECTIVE;
}
