// along_units - rtl/fx_along_pipe.v (Verilator, tb/along_units.v: eight configurations side by
// side) against model/fixed.c fx_along, called directly: every slot takes one operation a clock,
// each result is checked exactly LATENCY cycles later (the latency contract, pipe_latency.vh
// along_pipe_latency), bit for bit.
//
// The slots' configurations come from the build: -DALONG_SLOTS='{{W, MB, DIM, exhaustive}, ...}'
// with the same W, MB, DIM as the -G parameters of tb/along_units.v (tb/units.mk holds the one
// list). A slot marked exhaustive (W = 8 only) takes every d (all DIM lanes) with every rest
// word in 2D, or every d with a rest drawn per vector in 3D: 2^24 vectors. The other slots take
// N random vectors (the argument, default 1,000,000): edge lanes (0, +-1, +-2^k, +-(2^k - 1),
// the extremes), lanes of one size or of very different sizes, uniform ones, every rest width.
// Prints "PASS along_w<W>_mb<MB>_<DIM>d_<mode> (<count> vectors)" for each slot, or the first
// "FAIL along_...: ..." with the vector, and exits 1.

#include "Valong_units.h"
#include "verilated.h"

#include "fixed.h"

#include <cinttypes>
#include <cstdio>
#include <cstdlib>
#include <deque>
#include <memory>

namespace {

constexpr int LATENCY = 21;
constexpr int SLOTS = 8;
struct Cfg {
    int w, mb, dim, exhaustive;
};
constexpr Cfg CFG[SLOTS] = ALONG_SLOTS;

template <std::size_t N> uint64_t getf(const VlWide<N>& p, int lsb, int width)
{
    uint64_t v = 0;
    for (int i = 0; i < width; i++) v |= uint64_t((p.at((lsb + i) / 32) >> ((lsb + i) % 32)) & 1) << i;
    return v;
}
template <std::size_t N> void setf(VlWide<N>& p, int lsb, int width, uint64_t v)
{
    for (int i = 0; i < width; i++) {
        const int bit = lsb + i;
        EData& word = p.at(bit / 32);
        word = (word & ~(EData(1) << (bit % 32))) | (EData((v >> i) & 1) << (bit % 32));
    }
}

uint64_t rng_state = 0x9e3779b97f4a7c15ull;
uint64_t rnd()
{
    rng_state ^= rng_state << 13;
    rng_state ^= rng_state >> 7;
    rng_state ^= rng_state << 17;
    return rng_state;
}

struct Vec {
    fx_t d[3];
    uint32_t rest;
};

class Slot {
  public:
    Slot(int i, long random_n) : i_(i), c_(CFG[i]), fmt_{c_.w, c_.w / 2, c_.w - 1, c_.w - 1, c_.mb}
    {
        total_ = c_.exhaustive ? 1L << (3 * c_.w) : random_n; /* 2D: every d and rest; 3D: every d */
        std::snprintf(name_, sizeof name_, "w%d_mb%d_%dd_%s", c_.w, c_.mb, c_.dim, c_.exhaustive ? "exhaustive" : "random");
    }
    bool done() const { return issued_ >= total_ && checked_ >= total_; }
    const char* name() const { return name_; }
    long count() const { return checked_; }
    // this cycle's operation onto the inputs (none once every vector is issued)
    void drive(Valong_units& top)
    {
        Vec v{{0, 0, 0}, 0};
        const bool valid = issued_ < total_;
        if (valid) v = next();
        for (int k = 0; k < 3; k++)
            setf(top.d_all, i_ * 96 + k * c_.w, c_.w, k < c_.dim ? uint64_t(uint32_t(v.d[k])) & mask() : 0);
        setf(top.rest_all, i_ * 32, c_.w, v.rest & mask());
        queue_.push_back({v, valid});
        issued_ += valid;
    }
    // after the edge: the operation issued LATENCY cycles before is on the outputs
    bool check(const Valong_units& top)
    {
        if (int(queue_.size()) < LATENCY) return true;
        const Item it = queue_.front();
        queue_.pop_front();
        if (!it.valid) return true;
        fx_t t[3], rtl[3];
        const bool ok = fx_along(&fmt_, c_.dim, it.v.d, fx_t(it.v.rest), t);
        const bool rtl_ok = (top.ok_all >> i_) & 1;
        bool same = rtl_ok == ok;
        for (int k = 0; k < c_.dim; k++) {
            rtl[k] = sext(getf(top.t_all, i_ * 96 + k * c_.w, c_.w));
            same = same && rtl[k] == t[k];
        }
        checked_++;
        if (same) return true;
        std::printf("FAIL along_%s: d = (", name_);
        for (int k = 0; k < c_.dim; k++) std::printf("%s%" PRId32, k ? ", " : "", it.v.d[k]);
        std::printf(") rest = %" PRIu32 ": rtl t = (", it.v.rest);
        for (int k = 0; k < c_.dim; k++) std::printf("%s%" PRId32, k ? ", " : "", rtl[k]);
        std::printf(") ok %d, model t = (", int(rtl_ok));
        for (int k = 0; k < c_.dim; k++) std::printf("%s%" PRId32, k ? ", " : "", t[k]);
        std::printf(") ok %d (vector %ld)\n", int(ok), checked_);
        return false;
    }

  private:
    struct Item {
        Vec v;
        bool valid;
    };
    uint64_t mask() const { return (uint64_t(1) << c_.w) - 1; }
    fx_t sext(uint64_t v) const { return fx_t(int64_t(v << (64 - c_.w)) >> (64 - c_.w)); }
    Vec next()
    {
        Vec v{{0, 0, 0}, 0};
        if (c_.exhaustive) { // 2D: d.x, d.y, rest from the count; 3D: d.x, d.y, d.z, rest drawn
            const long n = issued_;
            for (int k = 0; k < c_.dim; k++) v.d[k] = sext(uint64_t(n >> (k * c_.w)) & mask());
            v.rest = uint32_t(c_.dim == 2 ? uint64_t(n >> (2 * c_.w)) & mask() : rnd() & mask());
            return v;
        }
        v.rest = rest_word();
        const bool same_size = rnd() % 4 == 0; // every lane of one size: the lead from any of them
        for (int k = 0; k < c_.dim; k++) v.d[k] = same_size && k ? fx_t(v.d[0] ^ fx_t(rnd() & 7)) : lane();
        for (int k = 0; k < c_.dim; k++) v.d[k] = sext(uint64_t(uint32_t(v.d[k])) & mask());
        return v;
    }
    fx_t lane()
    {
        const int w = c_.w, b = int(rnd() % w);
        const fx_t lo = fx_t(-(int64_t(1) << (w - 1))), hi = fx_t((int64_t(1) << (w - 1)) - 1);
        switch (rnd() % 8) {
        case 0: return fx_t(int64_t(rnd() % 5) - 2);
        case 1: return rnd() & 1 ? hi : lo;
        case 2: return b == w - 1 ? lo : fx_t((rnd() & 1 ? 1 : -1) * (int64_t(1) << b));
        case 3: return fx_t((rnd() & 1 ? 1 : -1) * ((int64_t(1) << b) - 1));
        default: return sext(rnd() & ((uint64_t(1) << (b + 1)) - 1));
        }
    }
    uint32_t rest_word()
    {
        const int b = int(rnd() % c_.w);
        switch (rnd() % 4) {
        case 0: return uint32_t(rnd() % 3);
        case 1: return uint32_t(((uint64_t(1) << b) - (rnd() & 1)) & mask());
        default: return uint32_t(rnd() & ((uint64_t(1) << (b + 1)) - 1) & mask());
        }
    }
    int i_;
    Cfg c_;
    fx_format fmt_;
    char name_[64];
    long total_ = 0, issued_ = 0, checked_ = 0;
    std::deque<Item> queue_;
};

}  // namespace

int main(int argc, char** argv)
{
    Verilated::commandArgs(argc, argv);
    const long random_n = argc > 1 ? std::atol(argv[1]) : 1000000;
    std::unique_ptr<Valong_units> top(new Valong_units);
    std::deque<Slot> slots;
    for (int i = 0; i < SLOTS; i++) {
        if (CFG[i].exhaustive && CFG[i].w != 8) {
            std::printf("FAIL along: slot %d is exhaustive at W = %d (only W = 8 is)\n", i, CFG[i].w);
            return 1;
        }
        slots.emplace_back(i, random_n);
    }
    auto tick = [&] {
        top->clk = 0;
        top->eval();
        top->clk = 1;
        top->eval();
    };
    top->reset = 1;
    tick();
    tick();
    top->reset = 0;
    bool all_done = false;
    while (!all_done) {
        all_done = true;
        for (Slot& s : slots) s.drive(*top);
        tick();
        for (Slot& s : slots) {
            if (!s.check(*top)) return 1;
            all_done = all_done && s.done();
        }
    }
    for (const Slot& s : slots) std::printf("PASS along_%s (%ld vectors)\n", s.name(), s.count());
    return 0;
}
