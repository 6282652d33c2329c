/* engine_double.c - the frame engine in double: the reference for fixed-point error. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "sim.h"

static inline double dbl_div(double a, double b, bool *zero)
{
    *zero = b == 0;
    return *zero ? 0 : a / b;
}

/* sqrt(h^2 - |d|^2); *miss when |d| > h (fx_leg's double twin) */
static inline double dbl_leg(double h, const double d[3], bool *miss)
{
    double r = h * h - (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    *miss = r < 0;
    return *miss ? 0 : sqrt(r);
}

#define SIM sim_dbl
#define P(name) sim_dbl_##name
#define NUM double
#define ADD(a, b) ((a) + (b))
#define SUB(a, b) ((a) - (b))
#define MUL(a, b) ((a) * (b))
#define AVG(a, b) (((a) + (b)) * 0.5)
#define HALF(a) ((a) * 0.5)
#define ABS(a) fabs(a)
#define LEN(d) sqrt((d)[0] * (d)[0] + (d)[1] * (d)[1] + (d)[2] * (d)[2])
#define DIV(a, b, dz) dbl_div((a), (b), (dz))
#define SDIV(a, b, dz) dbl_div((a), (b), (dz))
#define UNIT(a, b, dz) dbl_div((a), (b), (dz))
#define UMUL(a, u) ((a) * (u))
#define LEG(h, d, miss) dbl_leg((h), (d), (miss))
#define FROM(x) ((double)(x))
#define LESS(a, b) ((a) < (b))
#define MAC2(a, b, c, d) ((a) * (b) + (c) * (d))
#define ALONG(d, rest, t) dbl_along((d), (rest), (t))
#define SPRING_DIR(d, len, u) dbl_spring_dir((d), (len), (u))
#define DIRMUL(a, u) ((a) * (u))
#define UNITDIR(r, u) dbl_unit_dir((r), (u))

/* t = d (rest / |d|), false when |d| = 0 */
static inline bool dbl_along(const double d[3], double rest, double t[3])
{
    bool zero;
    double ratio = dbl_div(rest, LEN(d), &zero);
    for (int k = 0; k < 3; k++) t[k] = d[k] * ratio;
    return !zero;
}

/* |d| and d / |d|, false when |d| = 0 */
static inline bool dbl_spring_dir(const double d[3], double *len, double u[3])
{
    bool zero;
    *len = LEN(d);
    for (int k = 0; k < 3; k++) u[k] = 0;
    if (!(*len > 0)) return false;
    for (int k = 0; k < 3; k++) u[k] = dbl_div(d[k], *len, &zero);
    return true;
}

/* r / |r|, false when |r| = 0 */
static inline bool dbl_unit_dir(const double r[3], double u[3])
{
    double len;
    return dbl_spring_dir(r, &len, u);
}

#include "engine_body.h"
