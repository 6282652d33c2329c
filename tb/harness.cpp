// harness.cpp - the RTL and the cycle model in lockstep, every output, every cycle.
//
// Drives clk, reset, the scene's register writes, the scripted mouse and step on
// the Verilated sim_top (strand_core built for one scene, its observation port unpacked) and on the C cycle model
// (model/cycle.c), edge for edge, and compares every output of strand_core in every
// cycle. The first mismatch prints the cycle, each differing signal with both
// values, the phase and the indices, saves an FST trace of the run up to that
// cycle (the run is deterministic, so it is replayed with tracing on), and exits 1.
//
// Between the scripted events the inputs are noise from a seed: the mouse changes
// at arbitrary cycles (mid-frame and during reset; only the value present when a
// frame starts may matter), the read port address changes every cycle, and random
// idle gaps separate setup writes and frames.
//
// usage: harness SCENE [--frames N] [--seed S] [--trace FILE.fst] [--csv FILE] [--png FILE]
//                [--expect-fault flip|delay|boundary|slots_cut|bypass|hazard|graph_hazard|graph_boundary|stage_r|odd_pin|step_priority|norm_shift] [--mode lockstep|rtl|model] [--resets N] [--late-pins] [--png-dir DIR]
//                [--quiet] [--as-built] [--order serial|redblack] [--progress] [--json FILE]
//                [+verilator+rand+reset+2 +verilator+seed+N]
//
// --order replaces the scene's constraint order (as 'strand --order' does): redblack
// makes a chain's build the pipelined one (ARCH = 1); the harness must be built so
// (scripts/build_harness.sh SCENE DIR RTLDIR redblack).
// --png-dir DIR draws every frame the RTL computed (make movie). --as-built runs the
// model with the build's parameters where the scene would derive others (the effects
// gating check: an effect switched off in the build, its registers still written).
// --progress prints a line on stderr every 5 s (frame, cycles, rate): make sim passes it.
// --mode rtl runs the RTL alone and --mode model the cycle model alone, on the same
// stimulus (for make bench). --resets N asserts reset at N random cycles in the
// middle of frames; the run then writes the setup again and starts the scene over,
// and the RTL and the model must go on agreeing. --late-pins writes some of a chain's
// PINs during the init walk (two cycles before the walk writes the node, the cycle before,
// or in that cycle): the at-rest write of a node pinned two cycles before must see the pin,
// and one pinned later must not (a PIN reaches the flags through a register); and writes
// PREV_X and STEP_X again, changed, each in one cycle of the walk: the walk takes them from
// the second cycle after (it registers position + STEP and position + PREV a cycle
// ahead). In half the runs the scene's walk is the second one after the reset: a first
// walk (of the reset registers) comes before the setup writes, and the walk must have put
// its registers back for its next start.
//
// --json FILE writes every figure the run prints (and the ones a failure prints) as one
// JSON object, so that scripts read the run's counters, not its prose (the keys are those
// of Report's calls below; written whole or not at all).
//
// --expect-fault needs a build from a copy of the RTL with that fault planted
// (tb/faults.py): it passes only if the first mismatch is at the cycle the model
// predicts for that fault.

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

namespace {

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

// The run's figures, in the order they are printed, for --json: numbers and strings only.
struct Report {
    std::vector<std::pair<std::string, std::string>> kv;
    void num(const char *k, long v) { kv.emplace_back(k, std::to_string(v)); }
    void real(const char *k, double v) {
        char b[64];
        std::snprintf(b, sizeof b, std::isfinite(v) ? "%.17g" : "null", v);
        kv.emplace_back(k, b);
    }
    void str(const char *k, const std::string &v) {
        std::string q = "\"";
        for (char c : v) {
            if (c == '"' || c == '\\') q += '\\';
            if ((unsigned char)c < 0x20) { char b[8]; std::snprintf(b, sizeof b, "\\u%04x", c); q += b; continue; }
            q += c;
        }
        kv.emplace_back(k, q + "\"");
    }
    // written to FILE.tmp and renamed, so a reader finds the whole object or none
    bool write(const std::string &path) const {
        if (path.empty()) return true;
        FILE *f = std::fopen((path + ".tmp").c_str(), "w");
        if (!f) return false;
        std::fputs("{", f);
        for (size_t i = 0; i < kv.size(); i++)
            std::fprintf(f, "%s\n  \"%s\": %s", i ? "," : "", kv[i].first.c_str(), kv[i].second.c_str());
        std::fputs("\n}\n", f);
        return std::fclose(f) == 0 && std::rename((path + ".tmp").c_str(), path.c_str()) == 0;
    }
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

bool Run::compare() {
    cyc_outputs m;
    cyc_get_outputs(&model_, &m);
    // (name, rtl, model) of every output; names are only formatted on a mismatch
    uint64_t rtl[12 + 5 * CYC_MAX_LANES], mod[12 + 5 * CYC_MAX_LANES];
    int n = 0;
    auto put = [&](uint64_t a, uint64_t b) { rtl[n] = a, mod[n++] = b; };
    put(top_->frame_done, m.frame_done);
    put(top_->rd_x, m.rd_x);
    put(top_->rd_y, m.rd_y);
    put(top_->phase, (uint64_t)m.phase);
    put(top_->fv, m.fv);
    put(top_->fec, m.fec);
    put(top_->uidx, m.uidx);
    put(top_->nidx, m.nidx);
    put(top_->counter, m.counter);
    put(top_->rd_z, m.rd_z);
    put(top_->busy, m.busy);
    put(top_->irq, m.irq);
    for (int u = 0; u < hp_.wb; u++) {  // the write-back lanes
        put(lane(top_->wb_valid, u, 1), m.wb_valid[u]);
        put(lane(top_->wb_idx, u, hp_.iw), m.wb_idx[u]);
        put(lane(top_->wb_x, u, hp_.w), m.wb_x[u]);
        put(lane(top_->wb_y, u, hp_.w), m.wb_y[u]);
        put(lane(top_->wb_z, u, hp_.w), m.wb_z[u]);
    }
    bool ok = true;
    for (int i = 0; i < n; i++) {
        r_.digest = (r_.digest ^ rtl[i]) * 1099511628211ull;
        if (rtl[i] == mod[i]) continue;
        static const char *const names[] = {"frame_done", "rd_x", "rd_y", "phase", "fv", "fec", "uidx", "nidx", "counter", "rd_z", "busy", "irq"};
        static const char *const lanes[] = {"wb_valid", "wb_idx", "wb_x", "wb_y", "wb_z"};
        std::string name = i < 12 ? names[i] : std::string(lanes[(i - 12) % 5]) + "[" + std::to_string((i - 12) / 5) + "]";
        if (ok && !o_.quiet)
            std::printf("MISMATCH cycle %ld (phase %d, uidx %u, nidx %u, counter %u)\n", cyc_, m.phase, m.uidx, m.nidx, m.counter);
        if (!o_.quiet)
            std::printf("MISMATCH cycle %ld signal %s: rtl=0x%0*" PRIx64 " model=0x%0*" PRIx64 "\n", cyc_, name.c_str(),
                        (hp_.w + 3) / 4, rtl[i], (hp_.w + 3) / 4, mod[i]);
        ok = false;
    }
    return ok;
}

bool Run::cycle(const cyc_inputs &in) {
    top_->reset = in.reset;
    top_->mouse_x = in.mouse_x;
    top_->mouse_y = in.mouse_y;
    top_->mouse_z = in.mouse_z;
    top_->mouse_down = in.mouse_down;
    top_->step = in.step;
    top_->cfg_we = in.cfg_we;
    top_->cfg_addr = in.cfg_addr;
    top_->cfg_data = in.cfg_data;
    top_->rd_addr = in.rd_addr;
    if (rtl_on_) {
        top_->clk = 0;
        top_->eval();
    }
    if (tfp_) tfp_->dump((uint64_t)cyc_ * TRACE_PERIOD_PS);
    // the expected place of a planted fault, predicted from the model
    if (o_.expect == "flip" && r_.predicted_fault < 0) {
        cyc_outputs m;
        cyc_get_outputs(&model_, &m);
        if (m.wb_valid[0] && last_edge_verlet_ && ++fault_writes_ == 5) r_.predicted_fault = cyc_;
    }
    // stage_r: the first node a Verlet pass writes (in any unit) was stepped from its
    // successor's words, so a write-back lane shows it wrong the cycle after that write
    if (o_.expect == "stage_r" && r_.predicted_fault < 0 && last_edge_verlet_) {
        cyc_outputs m;
        cyc_get_outputs(&model_, &m);
        for (int l = 0; l < hp_.wb; l++)
            if (m.wb_valid[l]) r_.predicted_fault = cyc_;
    }
    // odd_pin: a row's odd node takes its even node's pinned flag, so the first Verlet write
    // (the second write port's lane) of a free odd node beside a pinned even one is missing
    if (o_.expect == "odd_pin" && r_.predicted_fault < 0 && last_edge_verlet_ && hp_.pair) {
        cyc_outputs m;
        cyc_get_outputs(&model_, &m);
        for (int u = 0; u < hp_.m; u++) {
            const int l = 2 * u + 1, node = u * hp_.k + (int)m.wb_idx[l];
            if (m.wb_valid[l] && model_.sc.pinned[node - 1] && !model_.sc.pinned[node]) r_.predicted_fault = cyc_;
        }
    }
    if (o_.expect == "delay" && r_.predicted_fault < 0) {
        cyc_outputs m;
        cyc_get_outputs(&model_, &m);
        if (m.fec) r_.predicted_fault = cyc_;
    }
    // boundary: the first sweep ends a cycle early, so the RTL shows the next colour in
    // the model's last cycle of the sweep, t = SP (FUSE: the fused sweep's, lag longer)
    const int first_lag = model_.st_fused ? model_.st_lag : 0;
    if (o_.expect == "boundary" && r_.predicted_fault < 0 && model_.st_running &&
        model_.st_t == hw_stream_period(&hp_) + first_lag)
        r_.predicted_fault = cyc_;
    // slots_cut: the first sweep ends after LP + 4 cycles where its slots need NS + 1 (a
    // slot-bound scene), so the RTL shows the next colour in the model's cycle t = LP + 5
    if (o_.expect == "slots_cut" && r_.predicted_fault < 0 && model_.st_running && model_.st_t == model_.lp + 5 + first_lag)
        r_.predicted_fault = cyc_;
    // bypass: every write of the pipelined pass lands a cycle early, so the RTL's write-back
    // lane shows the first one in the cycle in which the model writes it
    // hazard: unit 1 (streaming downward, its position 0 of colour 1) takes its even stream
    // positions in the first sweep where its odd ones are due; its position 0 (node K-1,
    // free and moving in the scene this runs on) is written at slot 0's write cycle
    // (LP + 3), where the model writes nothing, and shows on its lane the cycle after
    // (a sweep's writes land up to SP cycles into the next sweep: its time there is st_t + SP;
    // FUSE: the first sweep is the fused one, its slots and its length lag cycles later)
    const int fuse_lag = hp_.fuse ? model_.st_lag : 0;
    if (o_.expect == "hazard" && r_.predicted_fault < 0 && model_.st_running && model_.st_iter == 0 &&
        model_.st_t + (model_.st_colour ? model_.st_period + fuse_lag : 0) == 4 + model_.lp + fuse_lag)
        r_.predicted_fault = cyc_;
    // graph_hazard: graph_stream goes on to the next colour where it should drain, so the RTL
    // shows the next edge's a one cycle into the model's drain
    if (o_.expect == "graph_hazard" && r_.predicted_fault < 0 && model_.gs_state == GS_DRAIN && model_.gs_drain == model_.lp + 1)
        r_.predicted_fault = cyc_;
    // graph_boundary: the drain ends a cycle early, so the RTL reads the next edge's a in the
    // model's last drain cycle and shows it the cycle after
    if (o_.expect == "graph_boundary" && r_.predicted_fault < 0) {
        if (graph_drained_) r_.predicted_fault = cyc_;
        graph_drained_ = model_.gs_state == GS_DRAIN && model_.gs_drain == 0;
    }
    if (o_.expect == "bypass" && r_.predicted_fault < 0 && !in.reset && cyc_stream_write_due(&model_))
        r_.predicted_fault = cyc_;
    // norm_shift: the normaliser shifts lane x one bit too far, so the length of every link
    // with a large d.x comes out wrong: the pass's first write (in the scene this runs on, a
    // free node whose link lies mostly along x) lands with the wrong value and shows on its
    // write-back lane the cycle after
    if (o_.expect == "norm_shift" && r_.predicted_fault < 0 && !in.reset && cyc_stream_write_due(&model_))
        r_.predicted_fault = cyc_ + 1;
    // step_priority: a CMD beside a step in IDLE starts the chain's init walk instead of the
    // frame, so the RTL shows phase INIT the cycle after
    if (o_.expect == "step_priority" && r_.predicted_fault < 0 && !in.reset && in.step && in.cfg_we &&
        in.cfg_addr == STRAND_REG_CMD && (in.cfg_data & 1) && model_.phase == PH_IDLE && !hp_.graph)
        r_.predicted_fault = cyc_ + 1;
    if (compared_ && rtl_on_ && model_on_ && !compare()) {
        r_.ok = false;
        r_.mismatch_cycle = cyc_;
        return false;
    }
    // a pass writes its stage-D node at this edge, or (FUSE) the fused sweep's Verlet step its pair j
    const int fused_pair = model_.st_t - 2 - model_.st_lag;
    last_edge_verlet_ = (model_.pass_d || (model_.st_running && model_.st_fused && fused_pair >= 0 &&
                                           fused_pair < (hp_.k + 1) / 2)) && !in.reset;
    if (rtl_on_) {
        top_->clk = 1;
        top_->eval();
    }
    if (tfp_) tfp_->dump((uint64_t)cyc_ * TRACE_PERIOD_PS + TRACE_PERIOD_PS / 2);
    if (model_on_) cyc_edge(&model_, &in);
    cyc_++;
    if (in.reset) compared_ = true; // from the first reset edge on, nothing is left to chance
    return stop_at_ < 0 || cyc_ <= stop_at_;
}

// Reset with noise on every other input (all of it must be ignored), then the
// setup writes with random idle gaps, then the init walk. False if the run must stop.
bool Run::setup(cyc_inputs &in) {
    int reset_cycles = 1 + (int)rng_.below(4);
    for (int i = 0; i < reset_cycles; i++) {
        noise(in);
        in.reset = true;
        in.step = rng_.below(2);
        in.cfg_we = rng_.below(2);
        in.cfg_addr = rng_.below(1u << STRAND_REG_ADDR_BITS);
        in.cfg_data = (uint32_t)rng_.next() & mask_;
        if (!cycle(in)) return false;
    }
    in = cyc_inputs{};
    if (o_.late_pins && !hp_.graph && rng_.below(2)) { // a walk first, from idle after the reset
        for (uint32_t g = rng_.below(4); g > 0; g--) {
            noise(in);
            if (!cycle(in)) return false;
        }
        noise(in);
        in.cfg_we = true;
        in.cfg_addr = STRAND_REG_CMD;
        in.cfg_data = ((uint32_t)rng_.next() & mask_) | 1u;
        if (!cycle(in)) return false;
        in.cfg_we = false;
        do {
            noise(in);
            if (!cycle(in)) return false;
        } while (phase() != PH_IDLE);
    }
    std::vector<hw_write> writes(65536);
    {
        sim_fx tmp;
        sim_fx_init(&tmp, &sc_, &sc_.fmt);
        writes.resize((size_t)hw_setup_writes(&sc_, &tmp, writes.data(), (int)writes.size()));
        sim_fx_free(&tmp);
    }
    std::vector<std::pair<int, long>> late_pins; // node, the walk cycle its PIN is written in
    // --late-pins also writes PREV_X and STEP_X again, each in a drawn cycle of a chain's walk,
    // with its low bits changed: the walk takes the new value from the second cycle after
    long prev_cycle = -1, step_cycle = -1;
    uint32_t prev_data = 0, step_data = 0;
    for (const hw_write &w : writes) {
        if (o_.late_pins && !hp_.graph && w.addr == STRAND_REG_PREV_X && sc_.n_nodes > 1) {
            prev_cycle = (long)rng_.below((uint32_t)sc_.n_nodes - 1);
            prev_data = (w.data ^ 3u) & mask_;
        }
        if (o_.late_pins && !hp_.graph && w.addr == STRAND_REG_STEP_X && sc_.n_nodes > 1) {
            step_cycle = (long)rng_.below((uint32_t)sc_.n_nodes - 1);
            step_data = (w.data ^ 3u) & mask_;
        }
    }
    for (const hw_write &w : writes) {
        if (o_.late_pins && !hp_.graph && w.addr == STRAND_REG_PIN) {
            int node = -1;
            for (int i = 1; i < sc_.n_nodes && node < 0; i++)
                if (hw_node_addr(&hp_, i) == w.data) node = i;
            if (node > 0 && rng_.below(2)) {
                late_pins.emplace_back(node, std::max(0L, node - (long)rng_.below(3)));
                continue;
            }
        }
        for (uint32_t g = rng_.below(3); g > 0; g--) {
            noise(in);
            in.cfg_we = false;
            if (!cycle(in)) return false;
        }
        noise(in);
        in.cfg_we = true;
        in.cfg_addr = (uint32_t)w.addr;
        in.cfg_data = w.data;
        if (!cycle(in)) return false;
    }
    in.cfg_we = false;
    // The init walk writes node j (in node order) in its j-th cycle. --late-pins: a chain's
    // PIN of node i > 0 is held back and written in the walk's cycle i - 2, i - 1 or i
    // (drawn, from cycle 0), so that the walk's at-rest write meets a pin made two cycles
    // before it (which it sees), the cycle before and the same cycle (which it does not).
    // The scene then starts differently; model and RTL alike.
    long walk_cycle = 0;
    do {
        noise(in);
        in.cfg_we = false;
        if (phase() == PH_INIT) {
            for (size_t p = 0; p < late_pins.size(); p++)
                if (late_pins[p].second == walk_cycle) {
                    in.cfg_we = true;
                    in.cfg_addr = STRAND_REG_PIN;
                    in.cfg_data = hw_node_addr(&hp_, late_pins[p].first);
                    late_pins.erase(late_pins.begin() + (long)p);
                    break;
                }
            if (!in.cfg_we && walk_cycle == prev_cycle) {  // a pin took the cycle: none
                in.cfg_we = true;
                in.cfg_addr = STRAND_REG_PREV_X;
                in.cfg_data = prev_data;
            }
            if (!in.cfg_we && walk_cycle == step_cycle) {  // likewise
                in.cfg_we = true;
                in.cfg_addr = STRAND_REG_STEP_X;
                in.cfg_data = step_data;
            }
            walk_cycle++;
        }
        if (!cycle(in)) return false;
    } while (phase() != PH_IDLE);
    in.cfg_we = false;
    for (const auto &lp : late_pins) { // the ones whose cycle another pin took: after the walk
        in.cfg_we = true;
        in.cfg_addr = STRAND_REG_PIN;
        in.cfg_data = hw_node_addr(&hp_, lp.first);
        if (!cycle(in)) return false;
    }
    in.cfg_we = false;
    return true;
}

// A progress line on stderr at most every PROGRESS_SECONDS of wall time (and at the last
// frame once one was printed), so that a long run says how far it is.
void Run::progress(int done, int frames) {
    constexpr double PROGRESS_SECONDS = 5.0;
    auto now = std::chrono::steady_clock::now();
    if (!progress_started_) {
        progress_t0_ = progress_last_ = now;
        progress_started_ = true;
    }
    double since = std::chrono::duration<double>(now - progress_last_).count();
    if (since < PROGRESS_SECONDS && !(done == frames && progress_printed_)) return;
    double secs = std::chrono::duration<double>(now - progress_t0_).count();
    std::fprintf(stderr, "  frame %d of %d (%.0f %%), %ld cycles, %.0f s, %.0f cycles/s\n", done, frames,
                 100.0 * done / std::max(1, frames), cyc_, secs, secs > 0 ? cyc_ / secs : 0.0);
    progress_last_ = now;
    progress_printed_ = true;
}

Result Run::go(int frames) {
    cyc_inputs in{};
    if (!setup(in)) return r_;
    run_cycles_ = std::max(1L, (long)frames * hw_cycles_per_frame(&hp_));
    plan_reset();

    // The frames: the scripted mouse when a frame starts, noise otherwise. A random
    // reset (--resets) interrupts a frame; the setup is written again and the run
    // goes on from the scene's start, model and RTL alike.
    sim_dbl dbl;
    sim_dbl_init(&dbl, &sc_, nullptr);
    int n = sc_.n_nodes;
    for (int f = 0, scene_frame = 0; f < frames; f++, scene_frame++) {
        bool interrupted = false;
        for (uint32_t g = rng_.below(4); g > 0; g--) {
            noise(in);
            // the host acknowledges the frame-done interrupt in about half the gaps
            in.cfg_we = rng_.below(2);
            in.cfg_addr = STRAND_REG_IRQ_ACK;
            in.cfg_data = (uint32_t)rng_.next() & mask_;
            if (!cycle(in)) return r_;
            in.cfg_we = false;
        }
        double m[3];
        bool down;
        if (live_mouse) live_mouse(scene_frame, m, &down);
        else scene_mouse_at(&sc_, scene_frame, m, &down);
        noise(in);
        in.mouse_x = hw_word(&sc_.fmt, fx_from_double(&sc_.fmt, m[0]));
        in.mouse_y = hw_word(&sc_.fmt, fx_from_double(&sc_.fmt, m[1]));
        in.mouse_z = hw_word(&sc_.fmt, fx_from_double(&sc_.fmt, m[2]));
        in.mouse_down = sc_.en_mouse && down;
        if (quiet_mouse()) in.mouse_x = in.mouse_y = in.mouse_z = 0;
        in.step = true;
        // now and then a CMD in the same cycle: the step wins and the CMD is ignored
        if (rng_.below(4) == 0) {
            in.cfg_we = true;
            in.cfg_addr = STRAND_REG_CMD;
            in.cfg_data = ((uint32_t)rng_.next() & mask_) | 1u;
        }
        long start = cyc_;
        if (r_.first_frame_cycle < 0) r_.first_frame_cycle = cyc_;
        if (!cycle(in)) return r_;
        in.step = false;
        in.cfg_we = false;
        do {
            noise(in);
            if (reset_at_ >= 0 && cyc_ >= reset_at_) { // a reset in the middle of a frame
                r_.resets++;
                if (!setup(in)) return r_;
                plan_reset();
                interrupted = true;
                break;
            }
            if (phase() == PH_CONSTRAIN) r_.constrain_cycles++;
            if (phase() == PH_FORCE) r_.force_cycles++;
            if (!cycle(in)) return r_;
        } while (!frame_done());
        if (interrupted) { // start the scene again, in the model and in the double reference
            scene_frame = -1;
            sim_dbl_free(&dbl);
            sim_dbl_init(&dbl, &sc_, nullptr);
            continue;
        }
        long len = cyc_ - start;
        if (r_.frame_cycles_min < 0 || len < r_.frame_cycles_min) r_.frame_cycles_min = len;
        if (len > r_.frame_cycles_max) r_.frame_cycles_max = len;
        r_.frames = f + 1;
        if (o_.progress) progress(f + 1, frames);
        if (!model_on_) continue;
        sim_dbl_frame(&dbl);
        std::vector<double> frame_pos; // x, y, z of every node (z = 0 in 2D)
        for (int i = 0; i < n; i++)
            for (int a = 0; a < 3; a++) frame_pos.push_back(fx_to_double(&sc_.fmt, model_.s.pos[i][a]));
        if (!o_.png_dir.empty()) { // one picture per frame (make movie)
            if (f == 0) render_view_fit(&view_, &sc_, frames);
            char path[1024];
            std::snprintf(path, sizeof path, "%s/frame_%05d.png", o_.png_dir.c_str(), f + 1);
            render_png(&sc_, &view_, reinterpret_cast<double (*)[3]>(frame_pos.data()), f + 1, path);
        }
        if (frame_end && !frame_end(f + 1, frame_pos, len)) {
            r_.final_pos.push_back(frame_pos);
            break;
        }
        r_.final_pos.push_back(frame_pos);
        if (r_.final_pos.size() > 1 && o_.csv.empty()) r_.final_pos.erase(r_.final_pos.begin());
        dbl_err(dbl);
    }
    sim_dbl_free(&dbl);
    r_.cycles = cyc_;
    return r_;
}

}  // namespace

#ifndef STRAND_DEMO  // tb/demo.cpp includes this file for Run and has its own main
static int usage(const char *why) {
    if (why) std::fprintf(stderr, "harness: %s\n", why);
    std::fprintf(stderr, "usage: harness SCENE [--frames N] [--seed S] [--trace FILE.fst] [--csv FILE] [--png FILE]\n"
                         "               [--expect-fault flip|delay|boundary|slots_cut|bypass|hazard|graph_hazard|graph_boundary|stage_r|odd_pin|step_priority|norm_shift] [--mode lockstep|rtl|model] [--resets N] [--late-pins] [--quiet] [--as-built]\n"
                         "               [--order serial|redblack] [--progress] [--json FILE]\n"
                         "               [+verilator+rand+reset+2 +verilator+seed+N]\n");
    return 2;
}

int main(int argc, char **argv) {
    Options o;
    for (int i = 1; i < argc; i++) {
        std::string a = argv[i];
        auto value = [&](const char *name) -> const char * {
            if (i + 1 >= argc) {
                std::fprintf(stderr, "harness: %s needs a value\n", name);
                std::exit(2);
            }
            return argv[++i];
        };
        if (a == "--frames") {
            const char *v = value("--frames");
            char *end = nullptr;
            long n = std::strtol(v, &end, 10);
            if (!*v || *end || n < 0 || n > 100000000L) return usage(("--frames wants a whole number of frames >= 0, not '" + std::string(v) + "'").c_str());
            o.frames = (int)n;
        }
        else if (a == "--seed") o.seed = std::strtoull(value("--seed"), nullptr, 0);
        else if (a == "--trace") o.trace = value("--trace");
        else if (a == "--csv") o.csv = value("--csv");
        else if (a == "--png") o.png = value("--png");
        else if (a == "--expect-fault") o.expect = value("--expect-fault");
        else if (a == "--quiet") o.quiet = true;
        else if (a == "--progress") o.progress = true;
        else if (a == "--mode") o.mode = value("--mode");
        else if (a == "--png-dir") o.png_dir = value("--png-dir");
        else if (a == "--resets") o.resets = std::atoi(value("--resets"));
        else if (a == "--late-pins") o.late_pins = true;
        else if (a == "--as-built") o.as_built = true;
        else if (a == "--order") o.order = value("--order");
        else if (a == "--json") o.json = value("--json");
        else if (a == "--help") return usage(nullptr), 0;
        else if (a[0] == '+') continue; // Verilator's plusargs
        else if (a[0] == '-') return usage(("unknown option " + a).c_str());
        else if (o.scene.empty()) o.scene = a;
        else return usage(("unexpected argument " + a).c_str());
    }
    if (o.scene.empty()) return usage("no SCENE given");
    if (!o.expect.empty() && o.expect != "flip" && o.expect != "delay" && o.expect != "boundary" && o.expect != "bypass" &&
        o.expect != "slots_cut" && o.expect != "hazard" && o.expect != "graph_hazard" && o.expect != "graph_boundary" && o.expect != "norm_shift" &&
        o.expect != "stage_r" && o.expect != "odd_pin" && o.expect != "step_priority")
        return usage("--expect-fault takes flip, delay, boundary, slots_cut, bypass, hazard, graph_hazard, graph_boundary, stage_r, odd_pin, step_priority or norm_shift");
    if (o.mode != "lockstep" && o.mode != "rtl" && o.mode != "model") return usage("--mode takes lockstep, rtl or model");
    if (!o.order.empty() && o.order != "serial" && o.order != "redblack") return usage("--order takes serial or redblack");

    scene sc;
    char err[SCENE_ERR_LEN];
    if (!scene_load(&sc, o.scene.c_str(), err)) {
        std::fprintf(stderr, "%s\n", err);
        return 2;
    }
    if (!o.order.empty() && scene_set_order(&sc, o.order == "redblack" ? ORDER_REDBLACK : ORDER_SERIAL, err) < 0) {
        std::fprintf(stderr, "%s:1: --order: %s\n", sc.path, err);
        scene_free(&sc);
        return 2;
    }
    if (hw_check(&sc, err, sizeof err)) {
        std::fprintf(stderr, "%s\n", err);
        return 2;
    }
    hw_params hp, built;
    hw_params_of(&sc, &hp);
    // every parameter of the build params.h describes (the table of scripts/gen_params.py)
#define STRAND_BUILT(NAME, name, ...) built.name = STRAND_##NAME;
    STRAND_PARAMS(STRAND_BUILT)
#undef STRAND_BUILT
    STRAND_PARAMS_DERIVE(&built);
    bool same = true;
#define STRAND_SAME(NAME, name, ...) same = same && built.name == hp.name;
    STRAND_PARAMS(STRAND_SAME)
#undef STRAND_SAME
    // --as-built: the model takes the build's parameters (an effect the build leaves out
    // is left out of the model too, though the scene names it and its registers are written),
    // as strand_core passes them to its modules: a parameter whose switch is off is its default
    // there (ARCH = 1 with EN_CONSTRAINTS = 0 builds the serial node units)
    if (o.as_built) {
        hp = built;
        STRAND_PARAMS_PASSED(&hp, &built);
        STRAND_PARAMS_DERIVE(&hp);
    }
    else if (!same) {
        std::fprintf(stderr, "%s:1: this harness was built for another scene's parameters; build it for this one (make sim SCENE=%s)\n",
                     sc.path, sc.path);
        return 2;
    }
    int frames = o.frames >= 0 ? o.frames : sc.frames;

    auto t0 = std::chrono::steady_clock::now();
    Result r;
    {
        Run run(o, sc, hp, argc, argv, !o.trace.empty(), -1);
        r = run.go(frames);
    }
    double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

    Report rep;
    rep.str("scene", sc.name);
    rep.str("path", sc.path);
    rep.num("seed", (long)o.seed);
    rep.str("mode", o.mode);
    rep.num("units", hp.m);
    rep.num("frames", r.frames);
    rep.num("cycles", r.cycles);
    rep.num("resets", r.resets);
    // the run's verdict ("pass", "mismatch", "fault_caught", "fault_missed", "fault_elsewhere",
    // "cycles_per_frame") and the process's exit status, written with the figures
    auto finish = [&](const char *verdict, int status) {
        rep.str("verdict", verdict);
        rep.num("exit_status", status);
        if (!rep.write(o.json)) {
            std::fprintf(stderr, "harness: cannot write %s\n", o.json.c_str());
            status = status ? status : 2;
        }
        scene_free(&sc);
        return status;
    };

    if (!r.ok) {
        std::string fst = o.trace.empty() ? "mismatch.fst" : o.trace;
        if (o.trace.empty()) { // replay the same run with tracing on, up to just past the mismatch
            Options ot = o;
            ot.trace = fst;
            ot.quiet = true;
            ot.json.clear();
            Run replay(ot, sc, hp, argc, argv, true, r.mismatch_cycle + 2);
            replay.go(frames);
        }
        rep.num("mismatch_cycle", r.mismatch_cycle);
        rep.str("trace", fst);
        if (!o.expect.empty()) {
            bool right = r.mismatch_cycle == r.predicted_fault;
            std::printf("%s planted fault '%s': first mismatch at cycle %ld, expected at cycle %ld\n", right ? "PASS" : "FAIL",
                        o.expect.c_str(), r.mismatch_cycle, r.predicted_fault);
            rep.str("fault", o.expect);
            rep.num("fault_predicted_cycle", r.predicted_fault);
            return finish(right ? "fault_caught" : "fault_elsewhere", right ? 0 : 1);
        }
#ifdef STRAND_TRACE_TOP
        // this build traces the core's ports and observation port (every signal compared)
        const char *depth = " (the core's ports and observation port; make sim WAVES=1 traces every signal)";
#else
        const char *depth = "";
#endif
        std::printf("FAIL lockstep %s seed %" PRIu64 ": mismatch at cycle %ld; trace in %s%s\n", sc.name, o.seed,
                    r.mismatch_cycle, fst.c_str(), depth);
        return finish("mismatch", 1);
    }
    if (!o.expect.empty()) {
        std::printf("FAIL planted fault '%s' was not caught (expected at cycle %ld)\n", o.expect.c_str(), r.predicted_fault);
        rep.str("fault", o.expect);
        rep.num("fault_predicted_cycle", r.predicted_fault);
        return finish("fault_missed", 1);
    }

    if (!o.csv.empty()) {
        FILE *f = std::fopen((o.csv + ".tmp").c_str(), "w");
        if (f) {
            std::fprintf(f, sc.dim == 3 ? "frame,node,x,y,z\n" : "frame,node,x,y\n");
            for (size_t fr = 0; fr < r.final_pos.size(); fr++)
                for (int i = 0; i < sc.n_nodes; i++) {
                    const double *q = &r.final_pos[fr][(size_t)3 * i];
                    if (sc.dim == 3) std::fprintf(f, "%zu,%d,%.9g,%.9g,%.9g\n", fr + 1, i, q[0], q[1], q[2]);
                    else std::fprintf(f, "%zu,%d,%.9g,%.9g\n", fr + 1, i, q[0], q[1]);
                }
            if (std::fclose(f) == 0) std::rename((o.csv + ".tmp").c_str(), o.csv.c_str());
        }
    }
    if (!o.png.empty() && !r.final_pos.empty()) {
        render_view view;
        std::vector<double> p = r.final_pos.back();
        render_view_fit(&view, &sc, frames);
        render_png(&sc, &view, reinterpret_cast<double (*)[3]>(p.data()), frames, o.png.c_str());
    }
    double rms = r.err.samples ? std::sqrt(r.err.sum2 / (double)r.err.samples) : 0;
    // the physics throughput, counted on this run: constraint updates (node updates of the
    // centred rule, link updates of the pairwise rule) per clock over whole frames and over
    // the constraint passes alone
    long links = 0;
    for (int e = 0; e < sc.n_edges; e++) links += sc.edges[e].kind != EDGE_SPRING;
    const long updates = sc.en_constraints ? (long)sc.substeps * sc.iterations * (sc.rule == RULE_CENTRED ? sc.n_nodes : links) : 0;
    // and spring updates (one a spring edge) per clock in the spring passes
    const long springs = sc.en_springs ? (long)sc.substeps * (sc.n_edges - links) : 0;
    const double sim_rate = secs > 0 ? (double)r.cycles / secs : 0.0;
    rep.num("cycles_per_frame", r.frame_cycles_max);
    rep.num("cycles_per_frame_min", r.frame_cycles_min);
    rep.real("simulated_cycles_per_s", sim_rate);
    rep.num("constraint_updates_per_frame", updates);
    rep.num("spring_updates_per_frame", springs);
    if (r.frames >= 1 && r.frame_cycles_max >= 1) {
        const double per_frame = (double)updates / (double)r.frame_cycles_max;
        const double per_pass = r.constrain_cycles ? (double)updates * r.frames / (double)r.constrain_cycles : 0.0;
        const double spring_rate = r.force_cycles ? (double)springs * r.frames / (double)r.force_cycles : 0.0;
        rep.real("constraint_updates_per_clock", per_frame);
        rep.real("constraint_updates_per_clock_in_passes", per_pass);
        rep.real("spring_updates_per_clock_in_passes", spring_rate);
    }
    auto throughput = [&]() {
        if (r.frames < 1 || r.frame_cycles_max < 1) return;
        if (updates)
            std::printf("  constraint updates    %ld per frame: %.4f per clock over the frame, %.4f per clock in the "
                        "constraint passes (%d units)\n", updates, (double)updates / (double)r.frame_cycles_max,
                        r.constrain_cycles ? (double)updates * r.frames / (double)r.constrain_cycles : 0.0, hp.m);
        if (springs)
            std::printf("  spring updates        %ld per frame: %.4f per clock in the spring passes (%d units)\n", springs,
                        r.force_cycles ? (double)springs * r.frames / (double)r.force_cycles : 0.0, hp.m);
    };
    if (o.mode != "lockstep") {
        std::printf("%s alone %s: %d frames, %ld cycles (nothing compared)\n", o.mode == "rtl" ? "RTL" : "cycle model", sc.name,
                    r.frames, r.cycles);
        std::printf("  cycles per frame      %ld\n", r.frame_cycles_max);
        throughput();
        std::printf("  simulated cycles/s    %.0f\n", sim_rate);
        return finish("alone", 0);
    }
    // every frame takes the cycles of the one formula (model/timing.c), as the Icarus frame bench checks too
    const long formula = hw_cycles_per_frame(&hp);
    rep.num("cycles_per_frame_formula", formula);
    if (r.frames > 0 && (r.frame_cycles_min != formula || r.frame_cycles_max != formula)) {
        std::printf("FAIL lockstep %s seed %" PRIu64 ": frames took %ld to %ld cycles, the formula (hw_cycles_per_frame) says %ld\n",
                    sc.name, o.seed, r.frame_cycles_min, r.frame_cycles_max, formula);
        return finish("cycles_per_frame", 1);
    }
    char digest[17];
    std::snprintf(digest, sizeof digest, "%016" PRIx64, r.digest);
    rep.real("max_stretch_pct", r.err.stretch);
    rep.real("error_rms_rest_lengths", rms);
    rep.real("error_max_rest_lengths", r.err.worst);
    rep.str("output_digest", digest);
    std::printf("PASS lockstep %s seed %" PRIu64 ": %d frames, %ld cycles%s, every output equal in every cycle\n", sc.name, o.seed,
                r.frames, r.cycles, r.resets ? (", " + std::to_string(r.resets) + (r.resets == 1 ? " random reset" : " random resets")).c_str() : "");
    if (!o.quiet) {
        std::printf("  cycles per frame      %ld%s\n", r.frame_cycles_max,
                    r.frame_cycles_min == r.frame_cycles_max ? "" : " (varies: a bug)");
        throughput();
        std::printf("  simulated cycles/s    %.0f (RTL and model in lockstep)\n", sim_rate);
        std::printf("  max stretch           %.4f %%\n", r.err.stretch);
        std::printf("  error against double  rms %.3g, max %.3g rest lengths\n", rms, r.err.worst);
        std::printf("  output digest         %s\n", digest);
    }
    return finish("pass", 0);
}
#endif  // STRAND_DEMO
