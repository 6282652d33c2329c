// harness.h - the lockstep harness as a library: Options, Result and Run (the RTL under
// Verilator and the C cycle model, edge for edge, every output compared in every cycle).
// tb/harness_run.cpp implements Run; tb/harness.cpp (make sim, the lockstep runs) and
// tb/demo.cpp (make demo) are its two mains, each linked with it for one scene's build.
#ifndef STRAND_HARNESS_H
#define STRAND_HARNESS_H

#include <algorithm>
#include <chrono>
#include <functional>
#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "Vsim_top.h"
#include "verilated.h"
#include "verilated_fst_c.h"

#include "cycle.h"
#include "engine.h"
#include "hwgen.h"
#include "params.h"
#include "render.h"
#include "scene.h"
#include "strand_regs.h"

namespace strand_harness {

struct Options {
    std::string scene, trace, csv, png, expect, png_dir, json;
    std::string mode = "lockstep"; // lockstep | rtl (the RTL alone) | model (the cycle model alone)
    std::string order;             // serial | redblack: the scene's constraint order replaced
    bool as_built = false;         // the model follows the compiled build, not the scene's
    int resets = 0;                // resets at random cycles during the frames
    bool late_pins = false;        // a chain's PIN writes during the init walk (below)
    int frames = -1;
    uint64_t seed = 1;
    bool quiet = false;
    bool progress = false; // a line on stderr every few seconds: frame, cycles, rate
    long stop_at = -1; // replay: stop after this cycle
};

// The trace's time: one clock cycle is 10 ns (a 100 MHz clock, a round figure: the core's
// real clock is what its build reaches, docs/resources.md), the rising edge at 0 of each.
constexpr uint64_t TRACE_PERIOD_PS = 10000;

// splitmix64: the stimulus noise, reproducible from --seed
struct Rng {
    uint64_t s;
    uint64_t next() {
        uint64_t z = (s += 0x9e3779b97f4a7c15ull);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
        return z ^ (z >> 31);
    }
    uint32_t below(uint32_t n) { return n ? (uint32_t)(next() % n) : 0; }
};

// One lane of a bus: `width` bits at lane_index * width. Buses wider than 64 bits
// are VlWide arrays of 32-bit words; a lane of up to 32 bits spans at most two.
template <typename T> uint32_t lane(const T &bus, int lane_index, int width) {
    const uint64_t mask = width == 32 ? 0xffffffffull : (1ull << width) - 1;
    const int off = lane_index * width;
    if constexpr (sizeof(T) <= 8) {
        return (uint32_t)(((uint64_t)bus >> off) & mask);
    } else {
        const int word = off / 32, shift = off % 32;
        uint64_t v = bus[word];
        if (word + 1 < (int)(sizeof(T) / 4)) v |= (uint64_t)bus[word + 1] << 32;
        return (uint32_t)((v >> shift) & mask);
    }
}

struct Error {
    double sum2 = 0, worst = 0, stretch = 0;
    long samples = 0;
};

struct Result {
    Error err;
    bool ok = true;
    long cycles = 0, mismatch_cycle = -1, first_frame_cycle = -1;
    int frames = 0;
    long frame_cycles_min = -1, frame_cycles_max = -1;
    long constrain_cycles = 0;                // cycles in the constraint phase, over the frames
    long force_cycles = 0;                    // cycles in the spring pass (phase FORCE), over the frames
    uint64_t digest = 1469598103934665603ull; // FNV-1a over every output of every cycle
    long predicted_fault = -1;                // --expect-fault: the cycle the fault must show at
    int resets = 0;                           // random resets applied
    std::vector<std::vector<double>> final_pos;
};


class Run {
  public:
    Run(const Options &o, const scene &sc, const hw_params &hp, int argc, char **argv, bool trace, long stop_at)
        : o_(o), sc_(sc), hp_(hp), stop_at_(stop_at) {
        ctx_ = std::make_unique<VerilatedContext>();
        ctx_->commandArgs(argc, argv); // +verilator+rand+reset+2 +verilator+seed+N
        top_ = std::make_unique<Vsim_top>(ctx_.get());
        if (trace) {
            ctx_->traceEverOn(true);
            tfp_ = std::make_unique<VerilatedFstC>();
            top_->trace(tfp_.get(), 99);
            tfp_->open(o.trace.c_str());
        }
        cyc_init(&model_, &hp_);
        rng_.s = o.seed;
        rtl_on_ = o.mode != "model";
        model_on_ = o.mode != "rtl";
        resets_left_ = o.resets;
        mask_ = hp_.w == 32 ? 0xffffffffu : (1u << hp_.w) - 1;
    }
    ~Run() {
        if (tfp_) tfp_->close();
        top_->final();
        cyc_free(&model_);
    }

    Result go(int frames);

    // Live use (tb/demo.cpp): each frame's mouse comes from live_mouse instead of the
    // scene's script, and frame_end sees every frame's positions (the model's, equal to
    // the RTL's) and its cycles; returning false ends the run there.
    std::function<void(int frame, double m[3], bool *down)> live_mouse;
    std::function<bool(int frame, const std::vector<double> &pos, long frame_cycles)> frame_end;
    long cycles() const { return cyc_; }

  private:
    // One cycle: present the inputs, compare the outputs, then the rising edge on both sides.
    bool cycle(const cyc_inputs &in);
    bool compare();
    // fixed point (the RTL's, through the model) against double, at a frame end
    void dbl_err(const sim_dbl &dbl) {
        double scale = stats_length_scale(&sc_);
        std::vector<double> p((size_t)sc_.n_nodes * 3, 0.0);
        for (int i = 0; i < sc_.n_nodes; i++) {
            double e2 = 0;
            for (int a = 0; a < sc_.dim; a++) {
                double v = fx_to_double(&sc_.fmt, model_.s.pos[i][a]);
                p[(size_t)i * 3 + (size_t)a] = v;
                e2 += (v - dbl.pos[i][a]) * (v - dbl.pos[i][a]);
            }
            r_.err.sum2 += e2 / (scale * scale);
            r_.err.samples++;
            r_.err.worst = std::fmax(r_.err.worst, std::sqrt(e2) / scale);
        }
        r_.err.stretch = std::fmax(r_.err.stretch, stats_max_stretch(&sc_, reinterpret_cast<double (*)[3]>(p.data())));
    }
    void noise(cyc_inputs &in) {
        in.mouse_x = (uint32_t)rng_.next() & mask_;
        in.mouse_y = (uint32_t)rng_.next() & mask_;
        in.mouse_z = (uint32_t)rng_.next() & mask_;
        in.mouse_down = rng_.below(2);
        // A run traced on request (--trace) of a scene without a mouse holds the mouse at 0,
        // so that the waves show no stimulus the build ignores (every other run proves it is
        // ignored; a mismatch's replay, stop_at_ >= 0, keeps the noise it failed with).
        if (quiet_mouse()) in.mouse_x = in.mouse_y = in.mouse_z = 0, in.mouse_down = false;
        // mostly valid node addresses, sometimes any address
        uint32_t node = rng_.below((uint32_t)(hp_.m * hp_.k));
        in.rd_addr = rng_.below(8) ? hw_node_addr(&hp_, (int)node) : rng_.below(1u << (hp_.uw + hp_.iw));
    }
    bool quiet_mouse() const { return tfp_ && stop_at_ < 0 && !sc_.en_mouse; }

    const Options &o_;
    const scene &sc_;
    hw_params hp_;
    std::unique_ptr<VerilatedContext> ctx_;
    std::unique_ptr<Vsim_top> top_;
    std::unique_ptr<VerilatedFstC> tfp_;
    cyc_model model_;
    Rng rng_;
    uint32_t mask_;
    long stop_at_;
    long cyc_ = 0;       // cycles run (edges)
    bool progress_started_ = false, progress_printed_ = false;
    std::chrono::steady_clock::time_point progress_t0_, progress_last_;
    void progress(int done, int frames);
    bool compared_ = false; // outputs are compared from the first edge with reset on
    Result r_;
    int fault_writes_ = 0;
    bool graph_drained_ = false;  // graph_boundary: the model was in its last drain cycle
    bool last_edge_verlet_ = false;
    bool rtl_on_ = true, model_on_ = true;
    render_view view_{};
    long reset_at_ = -1; // the cycle of the next random reset, -1 for none
    int resets_left_ = 0;
    // What the stimulus waits on, from whichever side runs (they are equal in lockstep).
    int phase() const { return model_on_ ? model_.phase : (int)top_->phase; }
    bool frame_done() const { return model_on_ ? model_.frame_done : (bool)top_->frame_done; }
    bool setup(cyc_inputs &in);
    long run_cycles_ = 40000; // about the cycles of the frames to run: random resets land among them
    void plan_reset() {
        reset_at_ = resets_left_-- > 0 ? cyc_ + 1 + (long)rng_.below((uint32_t)std::min(40000L, run_cycles_)) : -1;
    }
};

}  // namespace strand_harness

#endif
