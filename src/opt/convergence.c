/* opt/convergence: the estimated relative distance to the minimum (see
 * convergence.h). */
#include "opt/convergence.h"

#include <math.h>

void opt_convergence_reset(opt_convergence *c)
{
    for (int i = 0; i <= OPT_CONV_WINDOW; i++) c->dec[i] = 0.0;
    for (int i = 0; i <= OPT_CONV_STALL; i++) c->low[i] = INFINITY;
    c->n = 0;
    c->criterion = INFINITY;
}

int opt_convergence_no_new_low(const opt_convergence *c)
{
    enum { S = OPT_CONV_STALL + 1 };
    return c->n >= S && !(c->low[c->n % S] > c->low[(c->n - 1) % S]);
}

double opt_convergence_update(opt_convergence *c, double e_before, double e_after, double decrement)
{
    enum { W = OPT_CONV_WINDOW + 1 };
    /* a rise (the objective of the iteration also holds its scaffold) is
     * movement all the same: its size counts */
    double d = fabs(e_before - e_after);
    if (!(d > 0.0)) d = 0.0;
    c->dec[c->n % W] = d;
    /* the lowest energy so far after each iteration (slot n % (S + 1)) */
    enum { S = OPT_CONV_STALL + 1 };
    double low = c->n > 0 ? c->low[(c->n - 1) % S] : e_before;
    if (e_after < low) low = e_after;
    c->low[c->n % S] = low;
    c->n++;
    if (c->n < W || !(e_after > 0.0)) return c->criterion = INFINITY;
    /* the largest ratio of consecutive decreases in the window; a decrease
     * after a zero one is a stall (rho_max) */
    double rho = 0.0;
    for (int k = 0; k < OPT_CONV_WINDOW; k++) {
        double older = c->dec[(c->n - W + k) % W], newer = c->dec[(c->n - W + k + 1) % W];
        double r = older > 0.0 ? newer / older : (newer > 0.0 ? OPT_CONV_RHO_MAX : 0.0);
        if (r > rho) rho = r;
    }
    if (rho > OPT_CONV_RHO_MAX) rho = OPT_CONV_RHO_MAX;
    /* the decrease due now if every decrease of the window shrank by rho:
     * one slow iteration after large ones is not the rate */
    double due = 0.0;
    for (int k = 0; k < W; k++) {
        double p = c->dec[(c->n - W + k) % W] * pow(rho, W - 1 - k);
        if (p > due) due = p;
    }
    double tail = due / e_after * rho / (1.0 - rho);
    double dn = decrement > 0.0 ? decrement : 0.0;
    double crit = tail > dn ? tail : dn;
    if (c->n >= S) {
        /* the lowest energy's progress over the window, and how far above
         * it the run is now (a rising energy is no stall) */
        double then = c->low[c->n % S], now = c->low[(c->n - 1) % S];
        double stall = (then - now > e_after - now ? then - now : e_after - now) / e_after;
        if (stall < crit) crit = stall;
    }
    return c->criterion = crit;
}
