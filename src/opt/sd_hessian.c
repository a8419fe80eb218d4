/* opt/sd_hessian: the symmetric Dirichlet case of opt/isotropic_hessian. */
#include "opt/sd_hessian.h"

#include "opt/isotropic_hessian.h"

int opt_sd_eigensystem(int d, const double *J, double *lambda, double *Q)
{
    return opt_isotropic_eigensystem(OPT_ENERGY_SYMMETRIC_DIRICHLET, d, J, lambda, Q);
}

int opt_sd_hessian(int d, const double *J, int project, double *H)
{
    return opt_isotropic_hessian(OPT_ENERGY_SYMMETRIC_DIRICHLET, d, J, project, H);
}

int opt_sd_simplex_hessian(const opt_simplices *S, int s, const double *X, int project, double *e,
                           double *g, double *H)
{
    return opt_isotropic_simplex_hessian(OPT_ENERGY_SYMMETRIC_DIRICHLET, S, s, X, project, e, g, H);
}
