/* tools/cli_progress: see cli_progress.h. */
#include "cli_progress.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/ioctl.h>
#include <unistd.h>

#include "base/timer.h"

enum { BAR_CELLS = 20 };
static const double REDRAW_SECONDS = 0.1;

void cli_progress_init(cli_progress *p, const char *cmd, int quiet)
{
    memset(p, 0, sizeof *p);
    p->cmd = cmd;
    const char *env = getenv("SCAF_PROGRESS");
    p->live = !quiet && isatty(fileno(stderr)) && !(env && !strcmp(env, "0"));
    p->every = env && !strcmp(env, "every");
    p->t_phase = timer_now();
    p->c_first = NAN;
}

int cli_progress_live(const cli_progress *p) { return p->live; }

static int terminal_width(void)
{
    struct winsize ws;
    if (ioctl(fileno(stderr), TIOCGWINSZ, &ws) == 0 && ws.ws_col >= 20) return ws.ws_col;
    return 80;
}

static void format_seconds(double s, char *buf, size_t size)
{
    if (!isfinite(s) || s < 0) snprintf(buf, size, "?");
    else if (s < 60) snprintf(buf, size, "%.0fs", ceil(s));
    else if (s < 3600) snprintf(buf, size, "%dm%02ds", (int)(s / 60), (int)fmod(s, 60));
    else snprintf(buf, size, "%dh%02dm", (int)(s / 3600), (int)fmod(s / 60, 60));
}

/* The bar: filled cells for fraction (clamped to 0..1). */
static void format_bar(double fraction, char *buf)
{
    if (!(fraction >= 0)) fraction = 0;
    if (fraction > 1) fraction = 1;
    int full = (int)(fraction * BAR_CELLS + 0.5);
    buf[0] = '[';
    for (int k = 0; k < BAR_CELLS; k++) buf[1 + k] = k < full ? '#' : '.';
    buf[1 + BAR_CELLS] = ']';
    buf[2 + BAR_CELLS] = '\0';
}

static int judged(double c) { return isfinite(c) && c > 0; }

void cli_progress_format(const cli_progress *p, int i, double energy, double criterion,
                         const char *extra, double elapsed, int width, char *buf, int size)
{
    char bar[BAR_CELLS + 3], count[64], crit[64] = "", e[48] = "", eta[32];
    double per_it = i > 0 ? elapsed / i : NAN;
    double fraction = 0, remaining = NAN;
    int cap = p->total;
    if (p->exact && cap > 0) {
        fraction = (double)i / cap;
        remaining = per_it * (cap - i);
        snprintf(count, sizeof count, "%d/%d", i, cap);
    } else {
        if (cap > 0) snprintf(count, sizeof count, "%d (cap %d)", i, cap);
        else snprintf(count, sizeof count, "%d", i);
        if (p->tolerance > 0 && judged(criterion)) {
            snprintf(crit, sizeof crit, "  criterion %.2g -> %.2g", criterion, p->tolerance);
            /* how far, on a log scale, the criterion came towards the tolerance */
            if (judged(p->c_first) && p->c_first > p->tolerance)
                fraction = log(p->c_first / criterion) / log(p->c_first / p->tolerance);
            if (criterion <= p->tolerance) {
                fraction = 1;
                remaining = 0;
            } else if (judged(p->c_first) && i > p->i_first && criterion < p->c_first) {
                double rate = log(p->c_first / criterion) / (i - p->i_first); /* per iteration */
                double left = log(criterion / p->tolerance) / rate;
                if (cap > 0 && left > cap - i) left = cap - i;
                remaining = per_it * left;
            }
        } else if (cap > 0) {
            fraction = (double)i / cap; /* no criterion: at worst the cap */
        }
        if (!(p->tolerance > 0) && cap > 0) remaining = per_it * (cap - i);
    }
    format_bar(fraction, bar);
    if (isfinite(energy)) snprintf(e, sizeof e, "  E %.6g", energy);
    format_seconds(remaining, eta, sizeof eta);
    int n = snprintf(buf, (size_t)size, "scaf %s: %s %s %s%s%s%s%s  ETA %s", p->cmd, p->phase, bar,
                     count, crit, e, extra ? "  " : "", extra ? extra : "", eta);
    int limit = width - 1 < size - 1 ? width - 1 : size - 1;
    if (n > limit && limit > 0) buf[limit] = '\0';
}

static void draw(cli_progress *p, const char *line)
{
    fprintf(stderr, "\r%s\033[K", line);
    fflush(stderr);
    p->drawn = 1;
    p->t_drawn = timer_now();
}

void cli_progress_phase(cli_progress *p, const char *name, int total, int exact, double tolerance)
{
    snprintf(p->phase, sizeof p->phase, "%s", name);
    p->total = total;
    p->exact = exact;
    p->tolerance = tolerance;
    p->t_phase = timer_now();
    p->c_first = NAN;
    p->i_first = 0;
    if (!p->live) return;
    char line[512];
    cli_progress_format(p, 0, NAN, NAN, NULL, 0, terminal_width(), line, (int)sizeof line);
    draw(p, line);
}

void cli_progress_step(cli_progress *p, int i, double energy, double criterion, const char *extra)
{
    if (!p->live) return;
    if (judged(criterion) && !judged(p->c_first)) {
        p->c_first = criterion;
        p->i_first = i;
    }
    double now = timer_now();
    int last = p->exact && p->total > 0 && i >= p->total;
    if (p->drawn && i > 1 && !last && !p->every && now - p->t_drawn < REDRAW_SECONDS) return;
    char line[512];
    cli_progress_format(p, i, energy, criterion, extra, now - p->t_phase, terminal_width(), line,
                        (int)sizeof line);
    draw(p, line);
}

void cli_progress_clear(cli_progress *p)
{
    if (!p->live || !p->drawn) return;
    fputs("\r\033[K", stderr);
    fflush(stderr);
    p->drawn = 0;
}

void cli_progress_done(cli_progress *p, const char *summary)
{
    if (!p->live) return;
    cli_progress_clear(p);
    if (summary) fprintf(stderr, "scaf %s: %s\n", p->cmd, summary);
    p->live = 0; /* later calls draw nothing */
}
