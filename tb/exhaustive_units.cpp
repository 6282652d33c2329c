// exhaustive_units - every operand of every arithmetic unit at one narrow width,
// RTL (Verilator, tb/exh_units.v) against the C model (model/fixed.c) called directly.
//
// At W = EXH_W, F = EXH_F, full SQRT_BITS/DIV_BITS = W-1:
//   fx_add, fx_sub, fx_mul, fx_avg  every (a, b) pair, 2^(2W) each; fx_half as avg(a, 0);
//                                   fx_mul's exact product output too
//   fx_sqrt                         every radicand below 2^(2W-2), plus a fixed-seed
//                                   sample of the saturating ones above
//   fx_div                          every (num, den) pair, den = 0 included
// The iterative units are also held to their latency contract on every operation:
// busy after edges 0..W-1, done (and not busy) after edge W.
// EXH_LANES copies of each unit are evaluated side by side.
// Prints one line per unit, "PASS exhaustive_wN_<unit> (<count> vectors)", or the first
// "FAIL exhaustive_wN_<unit>: ..." and exits with status 1.

#include "Vexh_units.h"
#include "verilated.h"

#include "fixed.h"

#include <cinttypes>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>

#ifndef EXH_W
#define EXH_W 12
#endif
#ifndef EXH_F
#define EXH_F 6
#endif
#ifndef EXH_LANES
#define EXH_LANES 16
#endif

namespace {

constexpr int W = EXH_W;
constexpr int L = EXH_LANES;
constexpr uint64_t WMASK = (uint64_t(1) << W) - 1;

fx_format fmt = {EXH_W, EXH_F, EXH_W - 1, EXH_W - 1, 0};

// Bit fields of Verilator ports, narrow (integers) or wide (VlWide).
template <std::size_t N> uint64_t getf(const VlWide<N>& p, int lsb, int width)
{
    const int wd = lsb / 32, sh = lsb % 32;
    uint64_t v = p.at(wd);
    if (wd + 1 < int(N)) v |= uint64_t(p.at(wd + 1)) << 32;
    return (v >> sh) & ((uint64_t(1) << width) - 1);
}
uint64_t getf(uint64_t p, int lsb, int width) { return (p >> lsb) & ((uint64_t(1) << width) - 1); }

template <std::size_t N> void setf(VlWide<N>& p, int lsb, int width, uint64_t v)
{
    for (int i = 0; i < width; i++) {
        const int bit = lsb + i;
        EData& word = p.at(bit / 32);
        word = (word & ~(EData(1) << (bit % 32))) | (EData((v >> i) & 1) << (bit % 32));
    }
}
template <typename T> void setf(T& p, int lsb, int width, uint64_t v)
{
    const uint64_t m = ((uint64_t(1) << width) - 1) << lsb;
    p = T((uint64_t(p) & ~m) | ((v << lsb) & m));
}

fx_t sext(uint64_t v)
{
    v &= WMASK;
    return (v >> (W - 1)) ? fx_t(int64_t(v) - int64_t(WMASK + 1)) : fx_t(v);
}

[[noreturn]] void fail(const char* unit, const char* what)
{
    std::printf("FAIL exhaustive_w%d_%s: %s\n", W, unit, what);
    std::fflush(stdout);
    std::exit(1);
}

char msg[512];

std::unique_ptr<VerilatedContext> ctx;
std::unique_ptr<Vexh_units> top;

// One clock cycle of the square roots (sqrt = true) or of the dividers.
bool tick_sqrt = true;
void tick()
{
    if (tick_sqrt) top->clk_sqrt = 1; else top->clk_div = 1;
    top->eval();
    if (tick_sqrt) top->clk_sqrt = 0; else top->clk_div = 0;
    top->eval();
}

constexpr uint64_t LANES_MASK = (L >= 64) ? ~uint64_t(0) : (uint64_t(1) << L) - 1;

// The combinational units, every pair.
void run_comb()
{
    long n_add = 0, n_mul = 0, n_avg = 0, n_half = 0;
    for (uint64_t ua = 0; ua <= WMASK; ua++) {
        top->a = ua;
        for (uint64_t ub0 = 0; ub0 <= WMASK; ub0 += L) {
            for (int j = 0; j < L; j++) setf(top->b, j * W, W, (ub0 + j) & WMASK);
            top->clk_comb = 1; // the wrapper registers a and b
            top->eval();
            top->clk_comb = 0;
            top->eval();
            for (int j = 0; j < L; j++) {
                const uint64_t ub = (ub0 + j) & WMASK;
                if (ub0 + j > WMASK) break;
                const fx_t a = sext(ua), b = sext(ub);
                const int64_t s = int64_t(a) + b, d = int64_t(a) - b;
                const uint64_t add_y = getf(top->add_y, j * W, W), sub_y = getf(top->sub_y, j * W, W);
                const uint64_t mul_y = getf(top->mul_y, j * W, W), avg_y = getf(top->avg_y, j * W, W);
                const int add_sat = int(getf(top->add_sat, j, 1)), sub_sat = int(getf(top->sub_sat, j, 1));
                const int mul_sat = int(getf(top->mul_sat, j, 1));
                if (add_y != (uint64_t(fx_add(&fmt, a, b)) & WMASK)
                    || add_sat != (s > fx_max(&fmt) || s < fx_min(&fmt))
                    || sub_y != (uint64_t(fx_sub(&fmt, a, b)) & WMASK)
                    || sub_sat != (d > fx_max(&fmt) || d < fx_min(&fmt))) {
                    std::snprintf(msg, sizeof msg, "a=%d b=%d: rtl add=%d sat=%d sub=%d sat=%d, model add=%d sub=%d",
                                  a, b, sext(add_y), add_sat, sext(sub_y), sub_sat, fx_add(&fmt, a, b), fx_sub(&fmt, a, b));
                    fail("fx_add", msg);
                }
                n_add += 2;
                const int64_t q = fx_round_shift(int64_t(a) * b, fmt.frac);
                const uint64_t prod = getf(top->mul_prod, j * 2 * W, 2 * W);
                const uint64_t prod_ref = uint64_t(int64_t(a) * b) & ((uint64_t(1) << (2 * W)) - 1);
                if (mul_y != (uint64_t(fx_mul(&fmt, a, b)) & WMASK)
                    || mul_sat != (q > fx_max(&fmt) || q < fx_min(&fmt)) || prod != prod_ref) {
                    std::snprintf(msg, sizeof msg, "a=%d b=%d: rtl=%d sat=%d prod=%" PRIx64 ", model=%d prod=%" PRIx64,
                                  a, b, sext(mul_y), mul_sat, prod, fx_mul(&fmt, a, b), prod_ref);
                    fail("fx_mul", msg);
                }
                n_mul++;
                if (avg_y != (uint64_t(fx_avg(&fmt, a, b)) & WMASK)) {
                    std::snprintf(msg, sizeof msg, "a=%d b=%d: rtl=%d, model=%d", a, b, sext(avg_y), fx_avg(&fmt, a, b));
                    fail("fx_avg", msg);
                }
                n_avg++;
                if (b == 0) {
                    if (avg_y != (uint64_t(fx_half(&fmt, a)) & WMASK)) {
                        std::snprintf(msg, sizeof msg, "a=%d: rtl=%d, model=%d", a, sext(avg_y), fx_half(&fmt, a));
                        fail("fx_half", msg);
                    }
                    n_half++;
                }
            }
        }
    }
    std::printf("PASS exhaustive_w%d_fx_add (%ld vectors)\n", W, n_add);
    std::printf("PASS exhaustive_w%d_fx_mul (%ld vectors)\n", W, n_mul);
    std::printf("PASS exhaustive_w%d_fx_avg (%ld vectors)\n", W, n_avg);
    std::printf("PASS exhaustive_w%d_fx_half (%ld vectors)\n", W, n_half);
}

// Run one operation on all lanes (operands already set) and hold the lanes to the
// latency contract. unit is "fx_sqrt" or "fx_div".
template <typename BusyT, typename DoneT>
void run_iterative(const char* unit, const BusyT& busy, const DoneT& done, int bits)
{
    top->start = 1;
    tick(); // edge 0
    top->start = 0;
    for (int e = 0; e <= bits; e++) {
        if (e > 0) tick(); // edges 1 .. bits
        if ((uint64_t(busy) & LANES_MASK) != LANES_MASK || (uint64_t(done) & LANES_MASK) != 0) {
            std::snprintf(msg, sizeof msg, "after edge %d: busy=%" PRIx64 " done=%" PRIx64 ", expected busy on, done off",
                          e, uint64_t(busy), uint64_t(done));
            fail(unit, msg);
        }
    }
    tick(); // edge bits + 1: rounding iteration, result
    if ((uint64_t(busy) & LANES_MASK) != 0 || (uint64_t(done) & LANES_MASK) != LANES_MASK) {
        std::snprintf(msg, sizeof msg, "after edge %d: busy=%" PRIx64 " done=%" PRIx64 ", expected busy off, done on",
                      bits + 1, uint64_t(busy), uint64_t(done));
        fail(unit, msg);
    }
}

bool sqrt_sat_exact(uint64_t rad)
{
    const int m = W - 1; // full bits: LSB = 0, clamped iff rad > 4^m - 2^m
    return (rad >> (2 * m)) != 0 || rad > (uint64_t(1) << (2 * m)) - (uint64_t(1) << m);
}

void run_sqrt()
{
    const uint64_t below = uint64_t(1) << (2 * (W - 1));
    long n = 0;
    uint64_t rng = 12345;
    auto check_batch = [&](const uint64_t* rad) {
        for (int j = 0; j < L; j++) setf(top->radicand, j * 2 * W, 2 * W, rad[j]);
        run_iterative("fx_sqrt", top->sqrt_busy, top->sqrt_done, fmt.sqrt_bits);
        for (int j = 0; j < L; j++) {
            const uint64_t y = getf(top->sqrt_y, j * W, W);
            const int sat = int(getf(top->sqrt_sat, j, 1));
            const fx_t ref = fx_sqrt(&fmt, rad[j]);
            if (y != uint64_t(ref) || sat != sqrt_sat_exact(rad[j])) {
                std::snprintf(msg, sizeof msg, "radicand=%" PRIu64 ": rtl=%" PRIu64 " sat=%d, model=%d",
                              rad[j], y, sat, ref);
                fail("fx_sqrt", msg);
            }
            n++;
        }
    };
    uint64_t rad[L];
    for (uint64_t r0 = 0; r0 < below; r0 += L) {
        for (int j = 0; j < L; j++) rad[j] = (r0 + j) % below;
        check_batch(rad);
    }
    // Saturating radicands: the edges and a fixed-seed sample.
    const uint64_t all = (uint64_t(1) << (2 * W)) - 1;
    for (int k = 0; k < 4096; k++) {
        for (int j = 0; j < L; j++) {
            rng = rng * 6364136223846793005ULL + 1442695040888963407ULL;
            rad[j] = below + (rng >> 33) % (all - below + 1);
        }
        if (k == 0) { rad[0] = below; rad[1] = below + 1; rad[2] = all; rad[3] = all - 1; rad[4] = 2 * below; }
        check_batch(rad);
    }
    std::printf("PASS exhaustive_w%d_fx_sqrt (%ld vectors)\n", W, n);
}

// Every den for num in [num_lo, num_hi); part names the PASS line.
void run_div(uint64_t num_lo, uint64_t num_hi, const char* part)
{
    long n = 0;
    for (uint64_t un = num_lo; un < num_hi; un++) {
        top->num = un;
        for (uint64_t d0 = 0; d0 <= WMASK; d0 += L) {
            for (int j = 0; j < L; j++) setf(top->den, j * W, W, (d0 + j) & WMASK);
            run_iterative("fx_div", top->div_busy, top->div_done, fmt.div_bits);
            for (int j = 0; j < L; j++) {
                const uint64_t ud = (d0 + j) & WMASK;
                const uint64_t y = getf(top->div_y, j * W, W);
                const int dbz = int(getf(top->div_dbz, j, 1)), sat = int(getf(top->div_sat, j, 1));
                bool ref_dbz = false;
                const fx_t ref = fx_div(&fmt, uint32_t(un), uint32_t(ud), &ref_dbz);
                // Clamped iff 2 * num * 2^F >= den * (2^W - 1) (full bits, ties up).
                const int ref_sat = ud != 0 && (un << (fmt.frac + 1)) >= ud * ((uint64_t(1) << W) - 1);
                if (y != uint64_t(ref) || dbz != int(ref_dbz) || sat != ref_sat) {
                    std::snprintf(msg, sizeof msg, "num=%" PRIu64 " den=%" PRIu64 ": rtl=%" PRIu64
                                  " dbz=%d sat=%d, model=%d dbz=%d sat=%d",
                                  un, ud, y, dbz, sat, ref, int(ref_dbz), ref_sat);
                    fail("fx_div", msg);
                }
                n++;
            }
        }
    }
    std::printf("PASS exhaustive_w%d_fx_div%s (%ld vectors)\n", W, part, n);
}

} // namespace

int main(int argc, char** argv)
{
    static_assert((WMASK + 1) % L == 0, "EXH_LANES must divide 2^W");
    if (const char* bad = fx_format_check(&fmt)) fail("format", bad);
    ctx.reset(new VerilatedContext);
    ctx->commandArgs(argc, argv);
    top.reset(new Vexh_units{ctx.get()});
    top->clk_comb = 0;
    top->clk_sqrt = 0;
    top->clk_div = 0;
    top->reset = 1;
    top->start = 0;
    for (int i = 0; i < 2; i++) {
        tick_sqrt = true;
        tick();
        tick_sqrt = false;
        tick();
    }
    top->reset = 0;
    if (top->sqrt_busy || top->sqrt_done || top->div_busy || top->div_done) fail("reset", "busy or done set after reset");
    // Optional arguments choose the parts to run (comb, sqrt, div, or div0 and
    // div1: the lower and upper half of the numerators), so that the make recipe
    // can run them in parallel; none means all.
    bool want_comb = argc < 2, want_sqrt = argc < 2, want_div = argc < 2, want_div0 = false, want_div1 = false;
    for (int i = 1; i < argc; i++) {
        const std::string arg = argv[i];
        if (arg == "comb") want_comb = true;
        else if (arg == "sqrt") want_sqrt = true;
        else if (arg == "div") want_div = true;
        else if (arg == "div0") want_div0 = true;
        else if (arg == "div1") want_div1 = true;
        else if (arg[0] != '+') fail("args", "arguments are comb, sqrt, div, div0, div1");
    }
    if (want_comb) run_comb();
    tick_sqrt = true;
    if (want_sqrt) run_sqrt();
    tick_sqrt = false;
    if (want_div) run_div(0, WMASK + 1, "");
    if (want_div0 && !want_div) run_div(0, (WMASK + 1) / 2, "_num_lower_half");
    if (want_div1 && !want_div) run_div((WMASK + 1) / 2, WMASK + 1, "_num_upper_half");
    top->final();
    return 0;
}
