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


#include "harness.h"

using namespace strand_harness;

namespace {

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

}  // namespace


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
