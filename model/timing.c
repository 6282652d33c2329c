/* timing.c - the cycle counts of the RTL (timing.h). Each function names the RTL it counts. */
#include "timing.h"

#include <stdio.h>

/* fx_along_pipe.v (the normalised datapath, MANTISSA > 0): |d| OR-ed, the leading ones, the funnels,
   their rounding, the squares (two stages), x, x's normalising, the ROM word, x' C0 (two stages),
   Newton's difference, Y1, R Y1 (two stages), Qm's shift, Qm, d Qm (two stages), the shift back, t */
long hw_along_pipe_latency(const hw_params *hp)
{
    (void)hp;
    return 21;
}

long hw_sqrt_latency(const hw_params *hp) { return hp->sqrt_bits + 2L; }

long hw_div_latency(const hw_params *hp) { return hp->div_bits + 2L; }

long hw_mul_pipe_latency(void) { return 2; }

long hw_toward_latency(const hw_params *hp)
{
    if (hp->mantissa) /* toward.v (toward_prev.v): one operation through toward_pipe (toward_prev_pipe), done the
                         cycle after its result */
        return hw_toward_pipe_latency(hp) + 1;
    if (hp->projection) /* toward_prev.v: the root of r.r, DIM unit divides, three phases of DIM products
                           (each used 3 cycles after its issue), p.p and rest^2, the leg's root, the last
                           phase, T formed, done */
        return 2L * hp->sqrt_bits + (long)hp->dim * hp->div_bits + 7L * hp->dim + 20;
    /* toward.v: DIM squares issued, the last used 2 cycles later (the multiplier pipeline), the
       root (fx_sqrt), the divide (fx_div), DIM products issued, the last used 3 cycles later
       (rounded in between), done */
    return hw_sqrt_latency(hp) + hw_div_latency(hp) + 2L * hp->dim + 6;
}

/* fx_sqrt_pipe.v and fx_div_pipe.v (rtl/pipe_latency.vh): a load stage, BITS + 1 iterations
   PIPE_STEPS to a stage, a rounding stage; BITS + 2 with one iteration a stage */
long hw_sqrt_pipe_latency(const hw_params *hp)
{
    return (hp->sqrt_bits + hp->pipe_steps) / hp->pipe_steps + 1L;
}

long hw_div_pipe_latency(const hw_params *hp)
{
    return (hp->div_bits + hp->pipe_steps) / hp->pipe_steps + 1L;
}

long hw_toward_pipe_latency(const hw_params *hp)
{
    if (hp->projection && hp->mantissa) /* toward_prev_pipe.v: q and r, u from fx_along_pipe, then as below from
                                           T_U: q.u, s u and p, p.p and rest^2, the leg's root, leg u, o, T, out */
        return hw_along_pipe_latency(hp) + hw_sqrt_pipe_latency(hp) + 23;
    if (hp->mantissa) /* toward_pipe.v: d, fx_along_pipe, T, the output register */
        return hw_along_pipe_latency(hp) + 3;
    if (hp->projection) /* toward_prev_pipe.v: q and r, r's squares and their sum, the root, the DIM unit
                           divides, q.u (products, rounding, two sums), s u and p, p.p and rest^2 (products,
                           sum, difference), the leg's root, leg u, o, T, the choice into the output registers */
        return 2L * hw_sqrt_pipe_latency(hp) + hw_div_pipe_latency(hp) + 28;
    /* toward_pipe.v: d, the squares (two stages), their sum, the root and the divide (each its
       latency and a register), the products (two stages), their rounding, T, the output register */
    return hw_sqrt_pipe_latency(hp) + hw_div_pipe_latency(hp) + 11L;
}

long hw_spring_pipe_latency(const hw_params *hp)
{
    if (hp->mantissa) /* spring_force_pipe.v: d, fx_along_pipe (u), len's products, len, len - rest, then as below
                         from T_U: the vn products ... the forces' rounding into the output register */
        return hw_along_pipe_latency(hp) + 15;
    /* spring_force_pipe.v: d, v_a, v_b; dv and |d|; the squares (two stages), their sum, the root
       (SQRT_BITS + 3), the DIM divides side by side (DIV_BITS + 3), u signed, the vn products (two
       stages) and their rounding, vn summed (two stages), ks (len - rest) and kd vn (two stages),
       their sum, f rounded, the forces (two stages), their rounding into the output register */
    return hw_sqrt_pipe_latency(hp) + hw_div_pipe_latency(hp) + 20L;
}

long hw_spring_sweep(const hw_params *hp)
{
    /* spring_stream.v: as a chain_stream sweep, with spring_force_pipe's latency */
    return hp->k + hw_spring_pipe_latency(hp) + 4;
}

long hw_spring_latency(const hw_params *hp)
{
    if (hp->mantissa) /* spring_force.v: one spring through spring_force_pipe, done the cycle after its result */
        return hw_spring_pipe_latency(hp) + 1;
    /* spring_force.v: DIM squares issued, the last used 2 cycles later (the multiplier pipeline),
       the root, DIM divides, DIM vn products and ks (len - rest), two waits for vn (products are
       used 3 cycles after their issue), kd vn, three waits for f, DIM F.k, the last used 3 cycles
       later, done */
    return hp->sqrt_bits + (long)hp->dim * hp->div_bits + 5L * hp->dim + 15;
}

static long node_count(const hw_params *hp) { return (long)hp->m * hp->k; }

/* chain_stream.v: a sweep's slots, NS = K/2 + 1 (slot j takes stream positions 2j-1 and 2j) */
static long stream_slots(const hw_params *hp) { return hp->k / 2 + 1; }

long hw_stream_period(const hw_params *hp)
{
    /* chain_stream.v: a sweep's cycles are t = 1 .. SP; every unit reads the pairs of stream
       positions (2j, 2j+1) at t = j + 1 (even units upward, odd ones downward), slots
       j = 0 .. NS-1 at t = j + 2; slot j's writes land in cycle j + LP + 3. The next sweep's
       t = 1 follows this one's t = SP when its reads follow those writes (its read of pair j,
       at this sweep's SP + j + 1, after slot j + 1's write: SP >= LP + 4) and this sweep's
       last slot has issued (slot NS-1 at t = NS + 1: SP >= NS + 1). */
    long slots1 = stream_slots(hp) + 1, lp4 = hw_toward_pipe_latency(hp) + 4;
    return slots1 > lp4 ? slots1 : lp4;
}

bool hw_stream_slot_bound(const hw_params *hp)
{
    /* a pipelined chain's sweeps wait for their slots, not for the pipe: NS + 1 > LP + 4 */
    return hp->arch && !hp->graph && hp->en_constraints &&
           stream_slots(hp) + 1 > hw_toward_pipe_latency(hp) + 4;
}

long hw_stream_last(const hw_params *hp)
{
    /* the pass's last sweep runs until its last write (slot NS-1's, cycle NS + LP + 2) lands */
    return stream_slots(hp) + hw_toward_pipe_latency(hp) + 2;
}

/* the pipelined passes: a chain's (chain_stream, spring_stream) and a graph's rods (graph_stream) */
static bool chain_streams(const hw_params *hp) { return hp->arch && !hp->graph; }
static bool graph_streams(const hw_params *hp) { return hp->arch && hp->graph && hp->en_constraints; }

long hw_constraint_pass(const hw_params *hp)
{
    long n = node_count(hp), rods = hp->graph ? hp->e_rods : n - 1;
    if (graph_streams(hp)) /* graph_stream: two cycles an edge, and the pipe drained after each colour
                              (the colour's last b written LP + 4 cycles after its first read; the
                              next colour reads the cycle after) */
        return 2 * rods + hp->colours * (hw_toward_pipe_latency(hp) + 3);
    if (hp->arch) /* chain_stream: two sweeps, even then odd (the pass's last sweep: hw_stream_last) */
        return 2 * hw_stream_period(hp);
    if (hp->rule == 0) /* chain_sequencer: load C and D, then per node two targets and the slide */
        return 2 + n * (2 * hw_toward_latency(hp) + 2);
    return rods * (hw_toward_latency(hp) + 5); /* pair_sequencer: read a, b, excess, write a, b */
}

long hw_spring_pass(const hw_params *hp)
{
    long springs = hp->graph ? hp->e_springs : node_count(hp) - 1;
    if (chain_streams(hp)) /* spring_stream: the start cycle, one sweep */
        return 1 + hw_spring_sweep(hp);
    return 1 + springs * (hw_spring_latency(hp) + 5); /* pair_sequencer SPRING: as pairwise, per link */
}

/* FUSE: the fused sweep's words come from node_unit's Verlet step, its stages R, A, B and C
   after their read, instead of the memories' (rtl/strand_defs.vh STRAND_FUSE_LAG) */
long hw_fuse_lag(void) { return 4; }

/* The terms of a substep and of a frame. */
long hw_pass_steps(const hw_params *hp) { return hp->pair ? (hp->k + 1) / 2 : hp->k; }
/* node_unit: K nodes (PAIR: K/2 rows, rounded up) through a four-stage pass (the last written 4
   cycles after its read; 5 with ARCH = 1, whose stage R registers the words first), FV; with
   constraints the sequencer starts the cycle after */
static long pass_stages(const hw_params *hp) { return hp->arch ? 5 : 4; }
/* FUSE: no Verlet pass, the first sweep takes the step: one cycle, the sequencer's start */
static long verlet_phase(const hw_params *hp)
{
    return hp->fuse ? 1 : hw_pass_steps(hp) + pass_stages(hp) + (hp->en_constraints ? 1 : 0);
}
static long constrain_phase(const hw_params *hp)
{
    if (!hp->en_constraints) return 0;
    if (chain_streams(hp)) /* 2 ITER sweeps, the last one to its drain; FUSE: the first one lag cycles longer */
        return (2L * hp->iter - 1) * hw_stream_period(hp) + hw_stream_last(hp) + (hp->fuse ? hw_fuse_lag() : 0);
    return hp->iter * hw_constraint_pass(hp);
}
static long spring_phase(const hw_params *hp) { return hp->en_springs ? hw_spring_pass(hp) : 0; }
static long ground_phase(const hw_params *hp) { return hp->en_ground ? hw_pass_steps(hp) + pass_stages(hp) : 0; }
static long grab_phase(const hw_params *hp) { return hp->grab && hp->en_mouse ? node_count(hp) + 1 : 0; }

long hw_cycles_per_frame(const hw_params *hp)
{
    long substep = verlet_phase(hp) + constrain_phase(hp) + spring_phase(hp) + ground_phase(hp);
    return hp->substeps * substep + 1 + grab_phase(hp);
}

int hw_timing_text(const hw_params *hp, char *out, int len)
{
    char pipe[320] = "", last[96] = "", steps[160] = "", verlet[96] = "";
    /* a pipelined chain (PAIR) steps two nodes a clock, one of each bank, in its Verlet and ground passes */
    const char *steps_term = hp->pair ? "ceil(K/2)" : "K";
    if (hp->arch) /* the pipes' root and divider: LSQ and LDV, BITS + 2 with one iteration a stage */
        snprintf(steps, sizeof steps, "; LSQ = ceil((SQRT_BITS + 1) / PIPE_STEPS) + 1 = %ld, LDV = ceil((DIV_BITS + 1) / PIPE_STEPS) + 1 = %ld",
                 hw_sqrt_pipe_latency(hp), hw_div_pipe_latency(hp));
    if (chain_streams(hp) && hp->en_constraints) /* the pass's last sweep runs to its drain */
        snprintf(last, sizeof last, "; a substep's last sweep SL = floor(K/2) + LP + 3 = %ld", hw_stream_last(hp));
    if (hp->fuse)
        snprintf(verlet, sizeof verlet, "1 + ");
    else
        snprintf(verlet, sizeof verlet, "Verlet (%s + %s with constraints, else K + %s) + ", steps_term, hp->arch ? "6" : "5",
                 hp->arch ? "5" : "4");
    if (hp->arch && hp->en_constraints)
        snprintf(pipe, sizeof pipe, "%s latency LP = %s = %ld%s\n", hp->projection ? "toward_prev_pipe" : "toward_pipe",
                 hp->projection ? (hp->mantissa ? "LA + LSQ + 23 (LA = fx_along_pipe's 21)" : "2 LSQ + LDV + 28")
                 : hp->mantissa ? "LA + 3 (LA = fx_along_pipe's 21)" : "LSQ + LDV + 11",
                 hw_toward_pipe_latency(hp), hp->mantissa ? "" : steps);
    return snprintf(out, (size_t)len,
                    "%s latency LT = %s = %ld\n"
                    "spring_force latency LS = %s = %ld\n"
                    "%s"
                    "constraint pass = %s = %ld%s\n"
                    "spring pass = %s = %ld\n"
                    "substep = %s%s [+ spring pass] [+ ground %s + %s] = %ld\n"
                    "frame = SUBSTEPS substeps + 1 [+ grab scan N + 1] = %ld cycles\n",
                    hp->projection ? "toward_prev" : "toward",
                    hp->mantissa ? (hp->projection ? "toward_prev_pipe's LA + LSQ + 23, + 1 (MANTISSA > 0)"
                                                   : "toward_pipe's LA + 3, + 1 (MANTISSA > 0)")
                    : hp->projection ? "2 SQRT_BITS + DIM DIV_BITS + 7 DIM + 20" : "SQRT_BITS + DIV_BITS + 2 DIM + 10",
                    hw_toward_latency(hp),
                    hp->mantissa ? "spring_force_pipe's LA + 15, + 1 (MANTISSA > 0)" : "SQRT_BITS + DIM DIV_BITS + 5 DIM + 15",
                    hw_spring_latency(hp), pipe,
                    graph_streams(hp) ? "2 E_RODS + COLOURS (LP + 3) (pipelined graph)"
                    : hp->arch        ? "2 sweeps of SP = max(floor(K/2) + 2, LP + 4) (pipelined)"
                    : hp->rule == 0 ? "2 + N (2 LT + 2) (centred)" : "links (LT + 5) (pairwise)",
                    hw_constraint_pass(hp), last,
                    chain_streams(hp) ? (hp->mantissa ? "1 + one sweep (K + LSP + 4), LSP = LA + 15 (pipelined)"
                                                      : "1 + one sweep (K + LSP + 4), LSP = LSQ + LDV + 20 (pipelined)")
                                      : "1 + links (LS + 5)",
                    hw_spring_pass(hp), verlet,
                    hp->fuse ? "ITER passes, the Verlet step in the first sweep ((2 ITER - 1) SP + SL + 4)"
                    : chain_streams(hp) ? "ITER passes ((2 ITER - 1) SP + SL)" : "ITER passes", steps_term, hp->arch ? "5" : "4",
                    verlet_phase(hp) + constrain_phase(hp) + spring_phase(hp) + ground_phase(hp),
                    hw_cycles_per_frame(hp));
}
