/* tools/cli_energy: see cli_energy.h. */
#include "cli_energy.h"

#include <string.h>

int cli_energy_parse(const char *v, scaf_energy *out)
{
    return scaf_energy_find(v, out) == SCAF_OK;
}

/* text in lines of at most width columns (a longer word gets its own
 * line), each indented by indent spaces. */
static void wrap(FILE *o, const char *text, int indent, int width)
{
    const char *w = text;
    while (*w) {
        int col = indent;
        fprintf(o, "%*s", indent, "");
        int first = 1;
        while (*w) {
            size_t n = strcspn(w, " ");
            if (!first && col + 1 + (int)n > width) break;
            if (!first) fputc(' ', o), col++;
            fwrite(w, 1, n, o);
            col += (int)n;
            first = 0;
            w += n;
            while (*w == ' ') w++;
        }
        fputc('\n', o);
    }
}

void cli_energy_help(FILE *o)
{
    fputs("energies (--energy NAME; the first is the default; every one is infinite at\n"
          "det J <= 0):\n",
          o);
    for (int e = 0; e < scaf_energy_count(); e++) {
        scaf_energy_info_t in;
        if (scaf_energy_info(e, &in) != SCAF_OK) continue;
        fputs("  ", o);
        for (const char *c = in.name; *c; c++) fputc(*c == '_' ? '-' : *c, o);
        if (in.aliases[0]) fprintf(o, " (or %s)", in.aliases);
        fputs(":\n", o);
        wrap(o, in.help, 4, 79);
    }
}
