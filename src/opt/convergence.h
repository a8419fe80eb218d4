/* opt/convergence: how far an iteration still is from its minimum.
 *
 * A scale-free estimate of the relative distance (E - E_min) / E from the
 * history of an optimization, used to stop the SCAF loop (app/param, the
 * atlas's settle phase). Two lower bounds of the truth are combined, and
 * the larger is the criterion:
 *   - the relative Newton decrement of the last step (Newton steps; 0
 *     otherwise): the decrease its quadratic model still predicts. Exact
 *     near a minimum where Newton converges quadratically, but an
 *     underestimate while convergence is linear (the SCAF loop re-rests
 *     its scaffold every iteration, which acts like a proximal term);
 *   - the linear tail: with the last decreases d_k of the energy shrinking
 *     by a ratio rho per iteration, the rest of the way is
 *     d_k rho / (1 - rho). rho is the LARGEST ratio of the last
 *     OPT_CONV_WINDOW iterations, at most OPT_CONV_RHO_MAX (a stalled or
 *     growing sequence counts as 100 d_k still to go), and d_k the
 *     largest of the window's decreases carried forward at that rate
 *     (d_j rho^(k - j)): one slow iteration does not make the run look
 *     converged.
 * Until OPT_CONV_WINDOW + 1 decreases are known the criterion is
 * +INFINITY (not yet judged). The SCAF loop's energy need not settle: its
 * scaffold is remeshed every iteration, and near the minimum the boundary
 * can go back and forth at a noise floor (bull_1: Newton decrements of
 * 5e-5 for 180 iterations while E moves by 1e-5 up and down, within 3e-5
 * of the best energy of 1000 iterations). So from OPT_CONV_STALL
 * iterations on, the criterion is at most the larger of the relative
 * progress of the LOWEST energy over the last OPT_CONV_STALL iterations
 * and the current energy's height above it: no progress over that window,
 * and no rise either, is convergence to the loop's resolution. Pure arithmetic;
 * nothing fails.
 */
#ifndef SCAF_OPT_CONVERGENCE_H
#define SCAF_OPT_CONVERGENCE_H

enum { OPT_CONV_WINDOW = 3, OPT_CONV_STALL = 10 };
#define OPT_CONV_RHO_MAX 0.99

typedef struct opt_convergence {
    double dec[OPT_CONV_WINDOW + 1]; /* the last decreases, newest at [(n - 1) % (W + 1)] */
    int n;                           /* decreases recorded */
    double low[OPT_CONV_STALL + 1];  /* the lowest energy so far after each of
                                        the last iterations, newest at
                                        [(n - 1) % (S + 1)] */
    double criterion;                /* the last value returned (+INFINITY at first) */
} opt_convergence;

/* 1 when the lowest energy did not go down over the last OPT_CONV_STALL
 * iterations: the run only moves up and down at its noise floor (the
 * SCAF loop's scaffold is remeshed every iteration, so E need not settle
 * to a fixed point; a settled chart drifts by 1e-10 relatively). */
int opt_convergence_no_new_low(const opt_convergence *c);

/* Forget the history (the energy being minimized changed). */
void opt_convergence_reset(opt_convergence *c);

/* Record one iteration of the energy being minimized, e_before -> e_after
 * (e_after > 0; a rise counts by its size: the run's objective also
 * holds the scaffold, so the mesh energy may rise a little while it falls), with the relative
 * Newton decrement of its step (0 when it was no Newton step), and return
 * the criterion: the estimated relative distance of e_after to the
 * minimum (see the banner). */
double opt_convergence_update(opt_convergence *c, double e_before, double e_after,
                              double decrement);

#endif /* SCAF_OPT_CONVERGENCE_H */
