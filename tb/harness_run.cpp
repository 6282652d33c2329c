// harness_run.cpp - Run's cycle, comparison, setup and frame loop (tb/harness.h).

#include "harness.h"

namespace strand_harness {


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

}  // namespace strand_harness
