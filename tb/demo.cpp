// demo.cpp - make demo: a person at the controls of the Verilated RTL.
//
// usage: demo SCENE [--frames N] [--events FILE] [--fmax MHz] [--seed S] [--screenshot FILE.png]
//
// An SDL2 window shows the body every frame while the RTL (strand_core built for the
// scene, as the lockstep harness builds it) runs frame after frame in lockstep with the
// C cycle model: every output is compared in every cycle, exactly as in make sim, and a
// mismatch stops the demo and says at which cycle. The real pointer drives the mouse
// inputs: its position (in the scene's coordinates: 2D scenes; a 3D view has no plane to
// point in, so there the scene's own mouse script plays) and its left button. The build
// decides the mouse's form (the reference-000 impulse, or grab: GRAB is a build
// parameter, so no key changes it), and the iterations and substeps (ITER and SUBSTEPS
// are build parameters too).
//
// Keys: space pauses and resumes, n (or the right arrow) runs one frame while paused, r
// starts the scene again, q or Escape quits. The HUD shows the frame, the cycles of the
// last frame, the simulated clock rate (cycles a second of RTL and model in lockstep on
// this machine), the frame rate this build would reach at --fmax MHz (default 50: give
// your build's figure from make synth), the largest stretch, the energy (heights above
// the lowest start, velocities from the last frame's motion) and the lockstep status.
//
// --events FILE feeds SDL's own event queue: each line "FRAME X Y BUTTON" (pixels of the
// window, BUTTON 1 held or 0 released) is pushed as a motion and a button event before
// that frame, so a run without a person (make test, under Xvfb) takes the same path as a
// hand on the mouse. --frames N stops after N frames. At the end the demo prints one
// line: frames, cycles in lockstep, and where the pointer and the node nearest it are.
// --screenshot FILE.png writes the window's last picture (HUD included) there.
// Exit status: 0, 1 on a lockstep mismatch (or a screenshot not written), 2 on bad input.
#include "harness.h"

#include <SDL.h>
#include <cairo.h>
#include <fstream>
#include <map>
#include <sstream>

using namespace strand_harness;

namespace {

struct Injected {
    int x, y;
    bool down;
};

// FRAME X Y BUTTON lines; '#' starts a comment. False (with file:line) on a bad line.
bool read_events(const std::string &path, std::map<int, Injected> &out) {
    std::ifstream in(path);
    if (!in) {
        std::fprintf(stderr, "%s: cannot open\n", path.c_str());
        return false;
    }
    std::string line;
    for (int n = 1; std::getline(in, line); n++) {
        line = line.substr(0, line.find('#'));
        std::istringstream ls(line);
        int frame, x, y, b;
        std::string rest;
        if (!(ls >> frame)) continue; // blank
        if (!(ls >> x >> y >> b) || (ls >> rest) || frame < 0 || (b != 0 && b != 1)) {
            std::fprintf(stderr, "%s:%d: want FRAME X Y BUTTON (BUTTON 0 or 1), not '%s'\n", path.c_str(), n, line.c_str());
            return false;
        }
        out[frame] = Injected{x, y, b == 1};
    }
    return true;
}

// Injected events carry this mouse id; with --events the display's own pointer (under
// Xvfb it sits mid-screen and reports itself as the window appears) is not listened to.
constexpr Uint32 INJECTED_MOUSE = 0x5354;

void push_pointer(const Injected &e, bool &was_down) {
    SDL_Event ev{};
    ev.type = SDL_MOUSEMOTION;
    ev.motion.which = INJECTED_MOUSE;
    ev.motion.x = e.x, ev.motion.y = e.y;
    SDL_PushEvent(&ev);
    if (e.down != was_down) {
        SDL_Event b{};
        b.type = e.down ? SDL_MOUSEBUTTONDOWN : SDL_MOUSEBUTTONUP;
        b.button.which = INJECTED_MOUSE;
        b.button.button = SDL_BUTTON_LEFT;
        b.button.x = e.x, b.button.y = e.y;
        SDL_PushEvent(&b);
        was_down = e.down;
    }
}

int usage_demo(const char *why) {
    if (why) std::fprintf(stderr, "demo: %s\n", why);
    std::fprintf(stderr, "usage: demo SCENE [--frames N] [--events FILE] [--fmax MHz] [--seed S] [--screenshot FILE.png]\n");
    return 2;
}

} // namespace

int main(int argc, char **argv) {
    Options o;
    std::string events_path, screenshot;
    long max_frames = -1;
    double fmax = 50;
    for (int i = 1; i < argc; i++) {
        std::string a = argv[i];
        auto value = [&]() -> std::string { return i + 1 < argc ? argv[++i] : std::string(); };
        if (a == "--frames") {
            std::string v = value();
            char *end = nullptr;
            max_frames = std::strtol(v.c_str(), &end, 10);
            if (v.empty() || *end || max_frames < 1) return usage_demo(("--frames wants a whole number >= 1, not '" + v + "'").c_str());
        } else if (a == "--events") events_path = value();
        else if (a == "--screenshot") screenshot = value();
        else if (a == "--fmax") {
            std::string v = value();
            char *end = nullptr;
            fmax = std::strtod(v.c_str(), &end);
            if (v.empty() || *end || !(fmax > 0)) return usage_demo(("--fmax wants MHz > 0, not '" + v + "'").c_str());
        } else if (a == "--seed") o.seed = std::strtoull(value().c_str(), nullptr, 0);
        else if (a[0] == '+') continue;
        else if (a[0] == '-') return usage_demo(("unknown option " + a).c_str());
        else if (o.scene.empty()) o.scene = a;
        else return usage_demo(("unexpected argument " + a).c_str());
    }
    if (o.scene.empty()) return usage_demo("no SCENE given");
    o.quiet = true;

    std::map<int, Injected> injected;
    if (!events_path.empty() && !read_events(events_path, injected)) return 2;

    scene sc;
    char err[SCENE_ERR_LEN];
    if (!scene_load(&sc, o.scene.c_str(), err)) {
        std::fprintf(stderr, "%s\n", err);
        return 2;
    }
    if (hw_check(&sc, err, sizeof err)) {
        std::fprintf(stderr, "%s\n", err);
        return 2;
    }
    hw_params hp;
    hw_params_of(&sc, &hp);
    if (hp.m != STRAND_M || hp.k != STRAND_K || hp.w != STRAND_W || hp.dim != STRAND_DIM) {
        std::fprintf(stderr, "%s:1: this demo was built for another scene's build (make demo SCENE=%s)\n", sc.path, sc.path);
        return 2;
    }

    render_view view{};
    render_view_fit(&view, &sc, sc.frames);
    view.live_pointer = sc.dim == 2; // 2D: the pointer is the person's, drawn below
    if (SDL_Init(SDL_INIT_VIDEO) != 0) {
        std::fprintf(stderr, "demo: SDL cannot open a display: %s (without one: xvfb-run make demo)\n", SDL_GetError());
        return 2;
    }
    SDL_Window *win = SDL_CreateWindow("Strand: the RTL in lockstep", SDL_WINDOWPOS_UNDEFINED, SDL_WINDOWPOS_UNDEFINED,
                                       view.width, view.height, 0);
    SDL_Renderer *ren = win ? SDL_CreateRenderer(win, -1, SDL_RENDERER_SOFTWARE) : nullptr;
    SDL_Texture *tex = ren ? SDL_CreateTexture(ren, SDL_PIXELFORMAT_ARGB8888, SDL_TEXTUREACCESS_STREAMING, view.width, view.height)
                           : nullptr;
    if (!tex) {
        std::fprintf(stderr, "demo: SDL: %s\n", SDL_GetError());
        return 2;
    }
    cairo_surface_t *surf = cairo_image_surface_create(CAIRO_FORMAT_RGB24, view.width, view.height);

    // the pointer, as the window reports it
    int ptr_x = 0, ptr_y = 0;
    bool ptr_down = false, inj_down = false, quit = false, paused = false, step_one = false, restart = false;
    long frames_total = 0, cycles_total = 0, mismatch_cycle = -1;
    std::vector<double> last_pos, prev_pos;
    double ref_height = 0;
    auto t_start = std::chrono::steady_clock::now();

    auto poll = [&]() {
        SDL_Event ev;
        while (SDL_PollEvent(&ev)) {
            bool is_mouse = ev.type == SDL_MOUSEMOTION || ev.type == SDL_MOUSEBUTTONDOWN || ev.type == SDL_MOUSEBUTTONUP;
            Uint32 which = ev.type == SDL_MOUSEMOTION ? ev.motion.which : ev.button.which;
            if (is_mouse && !injected.empty() && which != INJECTED_MOUSE) continue;
            if (ev.type == SDL_QUIT) quit = true;
            else if (ev.type == SDL_MOUSEMOTION) ptr_x = ev.motion.x, ptr_y = ev.motion.y;
            else if (ev.type == SDL_MOUSEBUTTONDOWN && ev.button.button == SDL_BUTTON_LEFT) ptr_down = true, ptr_x = ev.button.x, ptr_y = ev.button.y;
            else if (ev.type == SDL_MOUSEBUTTONUP && ev.button.button == SDL_BUTTON_LEFT) ptr_down = false;
            else if (ev.type == SDL_KEYDOWN) {
                switch (ev.key.keysym.sym) {
                case SDLK_q: case SDLK_ESCAPE: quit = true; break;
                case SDLK_SPACE: paused = !paused; break;
                case SDLK_n: case SDLK_RIGHT: step_one = true; break;
                case SDLK_r: restart = true; break;
                default: break;
                }
            }
        }
    };

    while (!quit) {
        restart = false;
        Run run(o, sc, hp, argc, argv, false, -1);
        run.live_mouse = [&](int frame, double m[3], bool *down) {
            double p[3];
            if (render_unproject(&sc, &view, ptr_x, ptr_y, p)) {
                m[0] = p[0], m[1] = p[1], m[2] = 0;
                *down = ptr_down;
            } else
                scene_mouse_at(&sc, frame, m, down); // 3D: the scene's script
        };
        run.frame_end = [&](int frame, const std::vector<double> &pos, long frame_cycles) {
            frames_total++;
            last_pos = pos;
            auto t_now = std::chrono::steady_clock::now();
            double secs = std::chrono::duration<double>(t_now - t_start).count();
            cycles_total = run.cycles();
            double (*p3)[3] = reinterpret_cast<double (*)[3]>(const_cast<double *>(pos.data()));
            double stretch = stats_max_stretch(&sc, p3);
            // energy: heights above the lowest start, velocities from the last frame's motion
            if (frame == 1) ref_height = stats_lowest(&sc, p3), prev_pos = pos;
            std::vector<double> vel(pos.size());
            for (size_t i = 0; i < pos.size(); i++) vel[i] = (pos[i] - prev_pos[i]) / sc.dt;
            double ke = 0, energy = stats_energy(&sc, p3, reinterpret_cast<double (*)[3]>(vel.data()), ref_height, &ke);
            prev_pos = pos;
            cairo_t *cr = cairo_create(surf);
            render_draw(cr, &sc, &view, reinterpret_cast<double (*)[3]>(const_cast<double *>(pos.data())), frame);
            char hud[4][160];
            std::snprintf(hud[0], sizeof hud[0], "cycles/frame %ld   simulated %.2f M cycles/s (RTL and model in lockstep)",
                          frame_cycles, secs > 0 ? cycles_total / secs / 1e6 : 0.0);
            std::snprintf(hud[1], sizeof hud[1], "at %.0f MHz this build runs %.0f frames/s   stretch %.2f %%   energy %.4g", fmax,
                          fmax * 1e6 / std::max(1L, frame_cycles), stretch, energy);
            std::snprintf(hud[2], sizeof hud[2], "lockstep: every output equal, %ld cycles   mouse %s%s", cycles_total,
                          STRAND_GRAB ? "grab" : "impulse", sc.dim == 3 ? " (3D: the scene's script)" : "");
            std::snprintf(hud[3], sizeof hud[3], "%sspace pause  n step  r restart  q quit", paused ? "PAUSED   " : "");
            if (view.live_pointer && sc.en_mouse) { // the pointer: a cross, red while the button is held
                cairo_set_source_rgb(cr, ptr_down ? 0.85 : 0.5, ptr_down ? 0.1 : 0.5, ptr_down ? 0.1 : 0.5);
                cairo_set_line_width(cr, 1.5);
                cairo_move_to(cr, ptr_x - 8, ptr_y), cairo_line_to(cr, ptr_x + 8, ptr_y);
                cairo_move_to(cr, ptr_x, ptr_y - 8), cairo_line_to(cr, ptr_x, ptr_y + 8);
                cairo_stroke(cr);
            }
            cairo_set_source_rgb(cr, 0.25, 0.25, 0.3);
            cairo_set_font_size(cr, 11);
            for (int l = 0; l < 4; l++) {
                cairo_move_to(cr, 8, 32 + 14 * l);
                cairo_show_text(cr, hud[l]);
            }
            cairo_destroy(cr);
            cairo_surface_flush(surf);
            SDL_UpdateTexture(tex, nullptr, cairo_image_surface_get_data(surf), cairo_image_surface_get_stride(surf));
            SDL_RenderClear(ren);
            SDL_RenderCopy(ren, tex, nullptr, nullptr);
            SDL_RenderPresent(ren);
            if (max_frames > 0 && frames_total >= max_frames) return false;
            // the next frame's injected pointer goes through SDL's queue like a real one
            auto e = injected.find((int)frames_total);
            if (e != injected.end()) push_pointer(e->second, inj_down);
            poll();
            while (paused && !step_one && !quit && !restart) {
                SDL_Delay(15);
                poll();
            }
            step_one = false;
            return !quit && !restart;
        };
        auto e0 = injected.find(0);
        if (frames_total == 0 && e0 != injected.end()) push_pointer(e0->second, inj_down);
        poll();
        Result r = run.go(1 << 30);
        if (!r.ok) {
            mismatch_cycle = r.mismatch_cycle;
            std::fprintf(stderr, "demo: lockstep MISMATCH at cycle %ld: the RTL and the cycle model disagree (make sim SCENE=%s "
                                 "reproduces a scripted run)\n", mismatch_cycle, sc.path);
            break;
        }
        if (max_frames > 0 && frames_total >= max_frames) break;
    }

    // where the pointer and the node nearest it are (the test of make demo reads this line)
    double p[3] = {0, 0, 0};
    bool have_ptr = render_unproject(&sc, &view, ptr_x, ptr_y, p);
    int nearest = -1;
    double best = 0;
    for (int i = 0; have_ptr && i < sc.n_nodes && !last_pos.empty(); i++) {
        double dx = last_pos[(size_t)i * 3] - p[0], dy = last_pos[(size_t)i * 3 + 1] - p[1];
        double d = std::sqrt(dx * dx + dy * dy);
        if (nearest < 0 || d < best) nearest = i, best = d;
    }
    std::printf("demo %s: %ld frames, %ld cycles, lockstep %s", sc.name, frames_total, cycles_total,
                mismatch_cycle < 0 ? "held" : "MISMATCH");
    if (nearest >= 0)
        std::printf("; pointer (%.4f, %.4f) %s, nearest node %d at (%.4f, %.4f), %.4f away", p[0], p[1], ptr_down ? "held" : "up",
                    nearest, last_pos[(size_t)nearest * 3], last_pos[(size_t)nearest * 3 + 1], best);
    std::printf("\n");
    bool write_failed = !screenshot.empty() && cairo_surface_write_to_png(surf, screenshot.c_str()) != CAIRO_STATUS_SUCCESS;
    if (write_failed) std::fprintf(stderr, "demo: cannot write %s\n", screenshot.c_str());
    cairo_surface_destroy(surf);
    SDL_DestroyTexture(tex);
    SDL_DestroyRenderer(ren);
    SDL_DestroyWindow(win);
    SDL_Quit();
    scene_free(&sc);
    return mismatch_cycle < 0 && !write_failed ? 0 : 1;
}
