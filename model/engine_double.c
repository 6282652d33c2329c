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
#define FROM(x) ((double)(x))
#define LESS(a, b) ((a) < (b))

#include "engine_body.h"
