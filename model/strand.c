/*
 * strand.c - the command-line tool: check, run and compare scenes.
 *
 * Exit status: 0 success (a diverging run is reported, not failed), 1 I/O failure, 2 bad input
 * (a scene error "file:line: message", or a bad argument). Nothing is written
 * before every argument and the scene have been checked; files are written to a
 * temporary name and renamed when complete.
 */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <getopt.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "engine.h"
#include "board.h"
#include "hwgen.h"
#include "render.h"
#include "scene.h"
#include "stability_bound.h"

#define EXIT_BAD_INPUT 2

static const char *usage_main =
    "usage: strand COMMAND [OPTIONS] SCENE\n"
    "\n"
    "Commands:\n"
    "  check SCENE      validate a scene; print a summary and its stability bound\n"
    "  run SCENE        run a scene and print frames, stretch, energy and drift\n"
    "  compare SCENE    run fixed point and double side by side and print the error\n"
    "  hwgen SCENE DIR  write the RTL parameters, setup writes, mouse script and expected\n"
    "                   positions of a scene into DIR (for the testbenches)\n"
    "  info SCENE       the RTL build the scene needs: every core parameter, the derived\n"
    "                   widths and the cycle counts (--json for scripts)\n"
    "  board --port DEV SCENE  run the scene on a board over its serial link (make bitstream)\n"
    "  set SCENE OUT SECTION.KEY=VALUE...  write OUT: SCENE with those keys set (checked)\n"
    "\n"
    "'strand COMMAND --help' describes each command's options.\n";

static const char *usage_check =
    "usage: strand check SCENE [--auto-substeps MAX] [--order serial|redblack] [--strict]\n"
    "Validate SCENE; print its summary and its stability bound, or 'file:line: message'\n"
    "and exit 2. Warnings on stderr, 'file:line: warning: ...': springs that cross the\n"
    "bound, and a constant the hardware uses (g h^2, ks h^2/m, kd h/m, damping, impulse,\n"
    "friction, rest lengths) that rounds to 0, loses more than 1 % to rounding or does not\n"
    "fit the number format, with the bits it needs.\n"
    "  --strict             exit 2 when there is a warning\n"
    "  --auto-substeps MAX  also print the fewest substeps (up to MAX) that meet the bound\n"
    "                       with a safety factor of 2 on the step\n";

static const char *usage_run =
    "usage: strand run SCENE [--frames N] [--format fixed|double] [--csv FILE] [--hex FILE] [--png DIR]\n"
    "                 [--auto-substeps MAX] [--order serial|redblack]\n"
    "  --frames N       frames to run (default: the scene's 'frames')\n"
    "  --format F       fixed (the scene's [format], or Q16.16) or double\n"
    "  --csv FILE       positions at every frame end: frame,node,x,y[,z] (fixed point: exact\n"
    "                   decimals; double: 17 significant digits; each reads back to its value)\n"
    "  --hex FILE       fixed only: raw positions at every frame end, one node per line,\n"
    "                   x y [z] as W-bit hex words (testbench vectors)\n"
    "  --png DIR        one picture per frame, DIR/frame_00001.png ...\n"
    "  --auto-substeps MAX  run with the fewest substeps (up to MAX) that meet the springs'\n"
    "                   stability bound with a safety factor of 2 on the step\n"
    "  --order O        the constraint pass's order instead of the scene's: serial, or\n"
    "                   redblack (even nodes or links first; graphs: by edge colour)\n";

static const char *usage_compare = "usage: strand compare SCENE [--frames N] [--auto-substeps MAX] [--order serial|redblack]\n"
                                   "Run the scene in fixed point and in double; print the RMS and largest position\n"
                                   "error (in rest lengths) and the largest stretch of each.\n"
                                   "  --auto-substeps MAX, --order O  as for 'strand run'\n";

static const char *usage_hwgen = "usage: strand hwgen SCENE DIR [--frames N] [--order serial|redblack]\n"
                                 "Write DIR/params.vh, config.hex, mouse.hex and expected.hex: what the RTL build\n"
                                 "and its frame-level testbench need for SCENE. Exit 2 if the RTL cannot run SCENE.\n";

static const char *usage_board = "usage: strand board --port DEV SCENE [--frames N] [--csv FILE] [--hex FILE]\n"
                                  "  Run the scene on a board (rtl/boards/: make bitstream BOARD=... SCENE=...) over\n"
                                  "  its serial link DEV (a serial device, or a pseudo-terminal): load it, run the\n"
                                  "  frames, read every node back after each. --csv as strand run --csv writes it;\n"
                                  "  --hex the raw words, as strand run --hex (they compare byte for byte).\n";
static const char *usage_info = "usage: strand info SCENE [--json | --vflags] [--order serial|redblack]\n"
                                "Print the strand_core build SCENE needs (every parameter, as 'strand hwgen' derives it),\n"
                                "its derived widths and its cycle counts (model/timing.c). With --json, one JSON object\n"
                                "for scripts: params, derived, timing, and rtl (false with why when the RTL cannot run\n"
                                "SCENE; the figures are then those of the build it would need). With --vflags, the\n"
                                "build as Verilog parameter overrides (-GW=32 -GEN_GRAVITY=1'b1 ...) on one line.\n";

static int bad_arg(const char *cmd, const char *fmt, const char *what)
{
    fprintf(stderr, "strand %s: ", cmd);
    fprintf(stderr, fmt, what);
    fprintf(stderr, "\n(see 'strand %s --help')\n", cmd);
    return EXIT_BAD_INPUT;
}

static bool parse_count(const char *s, int *out)
{
    char *end;
    long v;
    errno = 0;
    v = strtol(s, &end, 10);
    if (end == s || *end || errno || v < 0 || v > SCENE_MAX_FRAMES) return false;
    *out = (int)v;
    return true;
}

/* --order's value: a constraint_order, or -1 */
static int parse_order(const char *s)
{
    if (!strcmp(s, "serial")) return ORDER_SERIAL;
    if (!strcmp(s, "redblack")) return ORDER_REDBLACK;
    return -1;
}

typedef struct {
    int frames;       /* -1: the scene's */
    int format;       /* -1: the scene's */
    const char *csv, *hex, *png;
    int auto_substeps; /* 0: off; else the most substeps --auto-substeps may pick */
    int order;         /* -1: the scene's; else --order's constraint_order */
    bool strict;       /* check: warnings are errors */
    bool help;
} options;

/* Parse options after the command; returns the scene path, or NULL after reporting (status in *rc). */
static const char *parse_options(const char *cmd, int argc, char **argv, options *o, const char *allowed, int *rc)
{
    static const struct option longopts[] = {
        {"frames", required_argument, 0, 'f'}, {"format", required_argument, 0, 'F'}, {"csv", required_argument, 0, 'c'},
        {"hex", required_argument, 0, 'x'},    {"png", required_argument, 0, 'p'},    {"help", no_argument, 0, 'h'},
        {"auto-substeps", required_argument, 0, 'a'}, {"order", required_argument, 0, 'o'},
        {"strict", no_argument, 0, 's'},
        {0, 0, 0, 0},
    };
    int c;
    memset(o, 0, sizeof *o);
    o->frames = o->format = o->order = -1;
    opterr = 0;
    optind = 1;
    /* the leading ':' makes a missing value ':' rather than '?' */
    while ((c = getopt_long(argc, argv, ":h", longopts, NULL)) != -1) {
        if (c == 'h') {
            o->help = true;
            *rc = 0;
            return NULL;
        }
        if (c == ':') {
            *rc = bad_arg(cmd, "option '%s' needs a value", argv[optind - 1]);
            return NULL;
        }
        if (c == '?' || !strchr(allowed, c)) {
            *rc = bad_arg(cmd, "unknown option '%s'", argv[optind - 1]);
            return NULL;
        }
        switch (c) {
        case 'f':
            if (!parse_count(optarg, &o->frames)) {
                *rc = bad_arg(cmd, "--frames: '%s' is not a frame count (0..100000000)", optarg);
                return NULL;
            }
            break;
        case 'F':
            if (!strcmp(optarg, "fixed")) o->format = NUMBER_FIXED;
            else if (!strcmp(optarg, "double")) o->format = NUMBER_DOUBLE;
            else {
                *rc = bad_arg(cmd, "--format: '%s' is not 'fixed' or 'double'", optarg);
                return NULL;
            }
            break;
        case 'a':
            if (!parse_count(optarg, &o->auto_substeps) || o->auto_substeps < 1 || o->auto_substeps > SCENE_MAX_SUBSTEPS) {
                *rc = bad_arg(cmd, "--auto-substeps: '%s' is not a substep count (1..4096)", optarg);
                return NULL;
            }
            break;
        case 'o':
            if ((o->order = parse_order(optarg)) < 0) {
                *rc = bad_arg(cmd, "--order: '%s' is not 'serial' or 'redblack'", optarg);
                return NULL;
            }
            break;
        case 'c': o->csv = optarg; break;
        case 's': o->strict = true; break;
        case 'x': o->hex = optarg; break;
        case 'p': o->png = optarg; break;
        }
    }
    if (optind >= argc) {
        *rc = bad_arg(cmd, "%s", "no SCENE given");
        return NULL;
    }
    if (optind + 1 < argc) {
        *rc = bad_arg(cmd, "unexpected argument '%s'", argv[optind + 1]);
        return NULL;
    }
    return argv[optind];
}

/* Load a scene; order >= 0 (--order) replaces the scene's constraint order. */
static bool load(const char *path, scene *sc, int order)
{
    char err[SCENE_ERR_LEN];
    if (!scene_load(sc, path, err)) {
        fprintf(stderr, "%s\n", err);
        return false;
    }
    if (order >= 0 && scene_set_order(sc, (constraint_order)order, err) < 0) {
        fprintf(stderr, "%s:1: --order: %s\n", path, err);
        scene_free(sc);
        return false;
    }
    return true;
}

static const char *format_name(number_kind kind, const fx_format *fmt, char *buf, size_t len)
{
    if (kind == NUMBER_DOUBLE) snprintf(buf, len, "double");
    else if (fmt->mantissa)
        snprintf(buf, len, "Q%d.%d (W=%d, constraints on %d-bit mantissas; sqrt %d bits, div %d bits)", fmt->width - fmt->frac,
                 fmt->frac, fmt->width, fmt->mantissa, fmt->sqrt_bits, fmt->div_bits);
    else snprintf(buf, len, "Q%d.%d (W=%d, sqrt %d bits, div %d bits)", fmt->width - fmt->frac, fmt->frac, fmt->width, fmt->sqrt_bits, fmt->div_bits);
    return buf;
}

/* ---- the stability bound (stability_bound.h, docs/stability.md) ---- */

/* Warn on stderr, at the [springs] line, when the scene's step crosses the bound. */
/* Warns if the springs cross the stability bound; returns the number of warnings (0 or 1). */
static int warn_bound(const scene *sc)
{
    stab_bound b = stab_compute(sc, 0);
    if (!b.springs || b.index < 1) return 0;
    fprintf(stderr, "%s:%d: warning: the springs cross the stability bound at h = dt/%d = %.4g: h*omega = %.3g (limit 2), "
                    "h*kd/m = %.3g, index %.3g (limit 1)",
            sc->path, scene_section_line(sc, "springs"), sc->substeps, b.h, b.h_omega, b.h_kd_m, b.index);
    if (b.h_max > 0) fprintf(stderr, "; stable below h = %.4g, %d substeps or more; see --auto-substeps\n", b.h_max, (int)ceil(sc->dt / b.h_max));
    else fprintf(stderr, "; no step is stable%s\n", sc->integrator == INTEGRATOR_EULER ? " for explicit Euler without a damper" : "");
    return 1;
}

/* One constant the hardware rounds to the scene's format: a warning (returns 1) if it does
   not fit, rounds to 0, or loses more than 1 % to rounding; 0 if it is fine. */
static int warn_constant(const scene *sc, int line, const char *what, double v)
{
    const fx_format *f = &sc->fmt;
    int q_int = f->width - f->frac;
    double lsb = ldexp(1.0, -f->frac), got;
    /* the fraction bits that keep the rounding error (half an LSB) within 1 % of |v| */
    int frac_needed = (int)ceil(log2(50.0 / fabs(v)));
    if (v == 0) return 0;
    if (!fx_fits(f, v)) {
        fprintf(stderr, "%s:%d: warning: %s = %.6g does not fit Q%d.%d (largest %.6g): it saturates; it needs %d integer bits\n",
                sc->path, line, what, v, q_int, f->frac, fx_to_double(f, fx_max(f)), (int)floor(log2(fabs(v))) + 2);
        return 1;
    }
    got = fx_to_double(f, fx_from_double(f, v));
    if (got == 0) {
        fprintf(stderr, "%s:%d: warning: %s = %.6g rounds to 0 in Q%d.%d (%.3g LSB): the effect vanishes; it needs %d fraction bits "
                        "to hold it within 1 %%\n", sc->path, line, what, v, q_int, f->frac, fabs(v) / lsb, frac_needed);
        return 1;
    }
    if (fabs(got - v) > 0.01 * fabs(v)) {
        fprintf(stderr, "%s:%d: warning: %s = %.6g becomes %.6g in Q%d.%d (%+.1f %%): it needs %d fraction bits to hold it within 1 %%\n",
                sc->path, line, what, v, got, q_int, f->frac, 100 * (got - v) / v, frac_needed);
        return 1;
    }
    return 0;
}

/* Every pre-scaled constant of the scene (scene_constants), checked; returns the warnings. */
static int warn_constants(const scene *sc)
{
    scene_consts c;
    bool verlet = sc->integrator == INTEGRATOR_VERLET;
    int warnings = 0;
    char what[64];
    scene_constants(sc, &c);
    if (sc->en_springs) {
        warnings += warn_constant(sc, scene_key_line(sc, "springs", "ks"), verlet ? "ks h^2/m" : "ks/m", c.ks);
        warnings += warn_constant(sc, scene_key_line(sc, "springs", "kd"),
                                  verlet ? (sc->kd_per_step ? "kd h^2/m" : "kd h/m") : (sc->kd_per_step ? "kd h/m" : "kd/m"), c.kd);
    }
    if (sc->en_mouse) warnings += warn_constant(sc, scene_key_line(sc, "mouse", "impulse"), "the mouse impulse", c.impulse);
    if (sc->en_ground) warnings += warn_constant(sc, scene_key_line(sc, "ground", "friction"), "1 - friction", c.friction);
    STRAND_EFFECT_WARNINGS /* the effects table's constants */
    for (int e = 0; e < sc->n_edges; e++) {
        /* a chain's links share one rest length: one warning */
        if (sc->body == BODY_CHAIN && e > 0) break;
        snprintf(what, sizeof what, "the rest length of edge %d-%d", sc->edges[e].a, sc->edges[e].b);
        warnings += warn_constant(sc, sc->edges[e].line, sc->body == BODY_CHAIN ? "the chain's rest length" : what, sc->edges[e].rest);
    }
    return warnings;
}

static void print_bound(const scene *sc)
{
    stab_bound b = stab_compute(sc, 0);
    if (!b.springs) {
        printf("stability: no springs: constraints, gravity, mouse and ground have no step limit\n");
        return;
    }
    printf("stability: %s, %d springs at a node: omega = %.4g, h*omega = %.4g, h*kd/m = %.4g, index %.4g (%s below 1), ",
           sc->integrator == INTEGRATOR_EULER ? "euler" : "verlet", b.max_degree, b.omega, b.h_omega, b.h_kd_m, b.index,
           b.index < 1 ? "stable" : "UNSTABLE, must be");
    if (isinf(b.h_max)) printf("no step limit\n");
    else if (b.h_max > 0) printf("largest stable h %.4g\n", b.h_max);
    else printf("no stable step\n");
}

/* --auto-substeps: set the scene's substeps; false after reporting (exit 2) if none up to max will do. */
static bool apply_auto_substeps(const char *cmd, scene *sc, int max)
{
    int s = stab_auto_substeps(sc, max), was = sc->substeps;
    stab_bound b;
    if (s == 0) {
        fprintf(stderr, "%s:%d: strand %s --auto-substeps %d: no substep count up to %d meets the stability bound with a safety factor of %g\n",
                sc->path, scene_section_line(sc, "springs"), cmd, max, max, STAB_SAFETY);
        return false;
    }
    stab_set_substeps(sc, s);
    b = stab_compute(sc, 0);
    printf("auto-substeps: %d (the scene has %d): h = %.4g, h*omega = %.4g, index %.4g (safety factor %g on h)\n", s, was, b.h, b.h_omega,
           b.index, STAB_SAFETY);
    return true;
}

static int cmd_check(int argc, char **argv)
{
    options o;
    int rc = 0;
    scene sc;
    char fmtbuf[96], effects[160];
    int warnings;
    const char *path = parse_options("check", argc, argv, &o, "aos", &rc);
    if (!path) {
        if (o.help) fputs(usage_check, stdout);
        return rc;
    }
    if (!load(path, &sc, o.order)) return EXIT_BAD_INPUT;
    printf("ok %s: %s %dD, %d nodes (%d units x %d), %d edges, %s, %d frames x %d substeps x %d iterations, %s, effects: %s\n", sc.name,
           sc.body == BODY_CHAIN ? "chain" : "graph", sc.dim, sc.n_nodes, sc.units, sc.nodes_per_unit, sc.n_edges,
           format_name(sc.number, &sc.fmt, fmtbuf, sizeof fmtbuf), sc.frames, sc.substeps, sc.iterations,
           sc.integrator == INTEGRATOR_VERLET ? "verlet" : "euler", scene_effects_string(&sc, effects, sizeof effects));
    print_bound(&sc);
    warnings = warn_bound(&sc) + warn_constants(&sc);
    if (warnings && o.strict) {
        fprintf(stderr, "%s: %d warning(s) and --strict\n", sc.path, warnings);
        rc = EXIT_BAD_INPUT;
    }
    if (o.auto_substeps && !apply_auto_substeps("check", &sc, o.auto_substeps)) rc = EXIT_BAD_INPUT;
    scene_free(&sc);
    return rc;
}

/* ---- run ---- */

typedef struct {
    const scene *sc;
    FILE *csv, *hex;
    const char *png_dir;
    render_view view;
    bool failed;
} run_out;

/* One CSV coordinate that reads back to the same value: a fixed-point value (an integer over
   2^F, exact in a double) as its exact decimal, F fraction digits with the trailing zeros
   dropped; a double with 17 significant digits, enough for any double. */
static void csv_coordinate(FILE *f, const runner *r, double v)
{
    char buf[96];
    size_t n;
    if (r->kind != NUMBER_FIXED) {
        fprintf(f, ",%.17g", v);
        return;
    }
    snprintf(buf, sizeof buf, "%.*f", r->fx.fmt.frac, v);
    n = strlen(buf);
    while (n > 0 && buf[n - 1] == '0') buf[--n] = 0;
    if (n > 0 && buf[n - 1] == '.') buf[--n] = 0;
    fprintf(f, ",%s", strcmp(buf, "-0") ? buf : "0");
}

static bool run_hook(void *user, const runner *r, int frame, double (*pos)[3])
{
    run_out *out = user;
    const scene *sc = out->sc;
    if (out->csv)
        for (int i = 0; i < sc->n_nodes; i++) {
            fprintf(out->csv, "%d,%d", frame, i);
            for (int k = 0; k < sc->dim; k++) csv_coordinate(out->csv, r, pos[i][k]);
            fputc('\n', out->csv);
        }
    if (out->hex) {
        int digits = (r->fx.fmt.width + 3) / 4;
        uint32_t mask = r->fx.fmt.width == 32 ? 0xffffffffu : (1u << r->fx.fmt.width) - 1;
        for (int i = 0; i < sc->n_nodes; i++) {
            for (int k = 0; k < sc->dim; k++)
                fprintf(out->hex, "%s%0*x", k ? " " : "", digits, (unsigned)((uint32_t)r->fx.pos[i][k] & mask));
            fputc('\n', out->hex);
        }
    }
    if (out->png_dir) {
        char path[1024];
        snprintf(path, sizeof path, "%s/frame_%05d.png", out->png_dir, frame);
        if (!render_png(sc, &out->view, pos, frame, path)) {
            out->failed = true;
            return false;
        }
    }
    return true;
}

static FILE *open_temp(const char *path, char *tmp, size_t len)
{
    FILE *f;
    snprintf(tmp, len, "%s.tmp", path);
    f = fopen(tmp, "w");
    if (!f) fprintf(stderr, "strand run: cannot write %s: %s\n", tmp, strerror(errno));
    return f;
}

static bool close_temp(FILE *f, const char *tmp, const char *path, bool keep)
{
    bool ok = f && !ferror(f);
    if (f && fclose(f) != 0) ok = false;
    if (ok && keep && rename(tmp, path) == 0) return true;
    remove(tmp);
    if (keep) fprintf(stderr, "strand run: cannot write %s\n", path);
    return false;
}

static int cmd_run(int argc, char **argv)
{
    options o;
    int rc = 0, frames;
    scene sc;
    run_out out;
    run_stats st;
    number_kind kind;
    char csv_tmp[1100], hex_tmp[1100], fmtbuf[96];
    bool ok;
    const char *path = parse_options("run", argc, argv, &o, "fFcxpao", &rc);
    if (!path) {
        if (o.help) fputs(usage_run, stdout);
        return rc;
    }
    if (!load(path, &sc, o.order)) return EXIT_BAD_INPUT;
    if (o.auto_substeps && !apply_auto_substeps("run", &sc, o.auto_substeps)) {
        scene_free(&sc);
        return EXIT_BAD_INPUT;
    }
    warn_bound(&sc);
    kind = o.format >= 0 ? (number_kind)o.format : sc.number;
    frames = o.frames >= 0 ? o.frames : sc.frames;
    if (kind == NUMBER_FIXED && sc.number == NUMBER_DOUBLE) { /* a double scene run in fixed: check it fits */
        char buf[160];
        const char *msg = scene_check_format(&sc, &sc.fmt, buf, sizeof buf);
        if (msg) {
            fprintf(stderr, "%s:1: --format fixed: %s\n", sc.path, msg);
            scene_free(&sc);
            return EXIT_BAD_INPUT;
        }
    }
    if (o.hex && kind != NUMBER_FIXED) {
        scene_free(&sc);
        return bad_arg("run", "%s", "--hex writes raw fixed-point words: it needs --format fixed");
    }

    memset(&out, 0, sizeof out);
    out.sc = &sc;
    if (o.png) {
        if (mkdir(o.png, 0777) != 0 && errno != EEXIST) {
            fprintf(stderr, "strand run: cannot create %s: %s\n", o.png, strerror(errno));
            scene_free(&sc);
            return 1;
        }
        out.png_dir = o.png;
        render_view_fit(&out.view, &sc, frames);
    }
    if (o.csv && !(out.csv = open_temp(o.csv, csv_tmp, sizeof csv_tmp))) {
        scene_free(&sc);
        return 1;
    }
    if (o.hex && !(out.hex = open_temp(o.hex, hex_tmp, sizeof hex_tmp))) {
        close_temp(out.csv, csv_tmp, o.csv, false);
        scene_free(&sc);
        return 1;
    }
    if (out.csv) fprintf(out.csv, sc.dim == 3 ? "frame,node,x,y,z\n" : "frame,node,x,y\n");

    ok = run_scene(&sc, kind, &sc.fmt, frames, run_hook, &out, &st) && !out.failed;
    if (out.csv && !close_temp(out.csv, csv_tmp, o.csv, ok)) ok = false;
    if (out.hex && !close_temp(out.hex, hex_tmp, o.hex, ok)) ok = false;

    printf("%s: %d frames, %s, %d nodes\n", sc.name, st.frames, format_name(kind, &sc.fmt, fmtbuf, sizeof fmtbuf), sc.n_nodes);
    printf("max stretch %.4f %% (final %.4f %%)   energy %.6g -> %.6g   drift %+.6g (%+.3f %%)\n", st.max_stretch, st.final_stretch,
           st.energy0, st.energy, st.drift, st.drift_pct);
    if (sc.n_edges && st.frames > 0)
        printf("  max stretch: the largest |length - rest| / rest of any link in frames 1..%d: longest %.4f %% over its\n"
               "  rest (frame %d), shortest %.4f %% under it (frame %d); the scene as written (frame 0): %.4f %%\n",
               st.frames, st.max_longer, st.longer_frame, st.max_shorter, st.shorter_frame, st.initial_stretch);
    if (!st.finite)
        printf("warning: values became non-finite at frame %d: the integration diverged\n", st.first_nonfinite);
    if (st.skipped) printf("corrections skipped for zero lengths: %ld\n", st.skipped);
    if (st.fallbacks)
        printf("projection = previous: corrections along the current direction (no start direction, or its line misses the sphere): %ld\n",
               st.fallbacks);
    scene_free(&sc);
    return ok ? 0 : 1;
}

/* ---- compare ---- */

static int cmd_compare(int argc, char **argv)
{
    options o;
    int rc = 0, frames;
    scene sc;
    runner fx, dbl;
    double (*pf)[3], (*pd)[3];
    double sum2 = 0, worst = 0, stretch_fx = 0, stretch_dbl = 0, scale;
    long samples = 0;
    char fmtbuf[96];
    const char *path = parse_options("compare", argc, argv, &o, "fao", &rc);
    if (!path) {
        if (o.help) fputs(usage_compare, stdout);
        return rc;
    }
    if (!load(path, &sc, o.order)) return EXIT_BAD_INPUT;
    if (o.auto_substeps && !apply_auto_substeps("compare", &sc, o.auto_substeps)) {
        scene_free(&sc);
        return EXIT_BAD_INPUT;
    }
    warn_bound(&sc);
    {
        char buf[160];
        const char *msg = scene_check_format(&sc, &sc.fmt, buf, sizeof buf);
        if (msg) {
            fprintf(stderr, "%s:1: %s\n", sc.path, msg);
            scene_free(&sc);
            return EXIT_BAD_INPUT;
        }
    }
    frames = o.frames >= 0 ? o.frames : sc.frames;
    scale = stats_length_scale(&sc);
    pf = calloc((size_t)sc.n_nodes, sizeof *pf);
    pd = calloc((size_t)sc.n_nodes, sizeof *pd);
    if (!pf || !pd || !runner_init(&fx, &sc, NUMBER_FIXED, &sc.fmt) || !runner_init(&dbl, &sc, NUMBER_DOUBLE, NULL)) {
        fprintf(stderr, "strand compare: out of memory\n");
        return 1;
    }
    for (int f = 1; f <= frames; f++) {
        runner_frame(&fx);
        runner_frame(&dbl);
        runner_positions(&fx, pf);
        runner_positions(&dbl, pd);
        for (int i = 0; i < sc.n_nodes; i++) {
            double e2 = 0;
            for (int k = 0; k < 3; k++) e2 += (pf[i][k] - pd[i][k]) * (pf[i][k] - pd[i][k]);
            sum2 += e2;
            samples++;
            if (!(sqrt(e2) <= worst)) worst = sqrt(e2);
        }
        stretch_fx = fmax(stretch_fx, stats_max_stretch(&sc, pf));
        stretch_dbl = fmax(stretch_dbl, stats_max_stretch(&sc, pd));
    }
    printf("%s: %d frames, fixed %s against double\n", sc.name, frames, format_name(NUMBER_FIXED, &sc.fmt, fmtbuf, sizeof fmtbuf));
    printf("position error: rms %.6g, max %.6g rest lengths (rest length %g)\n", samples ? sqrt(sum2 / samples) / scale : 0, worst / scale,
           scale);
    printf("max stretch: fixed %.4f %%, double %.4f %%\n", stretch_fx, stretch_dbl);
    runner_free(&fx);
    runner_free(&dbl);
    free(pf);
    free(pd);
    scene_free(&sc);
    return isfinite(worst) ? 0 : 1;
}

static int cmd_hwgen(int argc, char **argv)
{
    scene sc;
    char err[SCENE_ERR_LEN];
    const char *pos[2] = {NULL, NULL};
    int npos = 0, frames = -1, order = -1;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) {
            fputs(usage_hwgen, stdout);
            return 0;
        } else if (!strcmp(argv[i], "--order")) {
            if (i + 1 >= argc || (order = parse_order(argv[i + 1])) < 0)
                return bad_arg("hwgen", "--order: '%s' is not 'serial' or 'redblack'", i + 1 < argc ? argv[i + 1] : "");
            i++;
        } else if (!strcmp(argv[i], "--frames")) {
            if (i + 1 >= argc || !parse_count(argv[i + 1], &frames))
                return bad_arg("hwgen", "--frames: '%s' is not a frame count (0..100000000)", i + 1 < argc ? argv[i + 1] : "");
            i++;
        } else if (argv[i][0] == '-') {
            return bad_arg("hwgen", "unknown option '%s'", argv[i]);
        } else if (npos < 2) {
            pos[npos++] = argv[i];
        } else {
            return bad_arg("hwgen", "unexpected argument '%s'", argv[i]);
        }
    }
    if (npos < 2) return bad_arg("hwgen", "%s", "needs SCENE and DIR");
    if (!load(pos[0], &sc, order)) return EXIT_BAD_INPUT;
    if (hw_check(&sc, err, sizeof err)) {
        fprintf(stderr, "%s\n", err);
        scene_free(&sc);
        return EXIT_BAD_INPUT;
    }
    if (!hw_export(&sc, pos[1], frames >= 0 ? frames : sc.frames, err, sizeof err)) {
        fprintf(stderr, "strand hwgen: %s\n", err);
        scene_free(&sc);
        return 1;
    }
    scene_free(&sc);
    return 0;
}

static int cmd_board(int argc, char **argv)
{
    scene sc;
    char err[SCENE_ERR_LEN];
    const char *path = NULL, *port = NULL, *csv_path = NULL, *hex_path = NULL;
    int frames = -1;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) {
            fputs(usage_board, stdout);
            return 0;
        } else if (!strcmp(argv[i], "--port") || !strcmp(argv[i], "--csv") || !strcmp(argv[i], "--hex")) {
            if (i + 1 >= argc) return bad_arg("board", "%s needs a value", argv[i]);
            const char **dst = !strcmp(argv[i], "--port") ? &port : !strcmp(argv[i], "--csv") ? &csv_path : &hex_path;
            *dst = argv[++i];
        } else if (!strcmp(argv[i], "--frames")) {
            if (i + 1 >= argc || !parse_count(argv[i + 1], &frames))
                return bad_arg("board", "--frames: '%s' is not a frame count (0..100000000)", i + 1 < argc ? argv[i + 1] : "");
            i++;
        } else if (argv[i][0] == '-') {
            return bad_arg("board", "unknown option '%s'", argv[i]);
        } else if (!path) {
            path = argv[i];
        } else {
            return bad_arg("board", "unexpected argument '%s'", argv[i]);
        }
    }
    if (!path || !port) return bad_arg("board", "%s", "needs --port DEV and SCENE");
    if (!load(path, &sc, -1)) return EXIT_BAD_INPUT;
    if (hw_check(&sc, err, sizeof err)) {
        fprintf(stderr, "%s\n", err);
        scene_free(&sc);
        return EXIT_BAD_INPUT;
    }
    char csv_tmp[1100], hex_tmp[1100];
    FILE *csv = NULL, *hex = NULL;
    if (csv_path && !(csv = open_temp(csv_path, csv_tmp, sizeof csv_tmp))) {
        scene_free(&sc);
        return 1;
    }
    if (hex_path && !(hex = open_temp(hex_path, hex_tmp, sizeof hex_tmp))) {
        close_temp(csv, csv_tmp, csv_path, false);
        scene_free(&sc);
        return 1;
    }
    if (csv) fprintf(csv, sc.dim == 3 ? "frame,node,x,y,z\n" : "frame,node,x,y\n");
    int n = frames >= 0 ? frames : sc.frames;
    bool ok = board_run(&sc, port, n, csv, hex, err, sizeof err);
    if (!ok) fprintf(stderr, "strand board: %s\n", err);
    if (csv && !close_temp(csv, csv_tmp, csv_path, ok)) ok = false;
    if (hex && !close_temp(hex, hex_tmp, hex_path, ok)) ok = false;
    if (ok) printf("%s: %d frames on the board at %s%s%s%s%s\n", sc.name, n, port, csv_path ? ", positions in " : "",
                   csv_path ? csv_path : "", hex_path ? ", words in " : "", hex_path ? hex_path : "");
    scene_free(&sc);
    return ok ? 0 : 1;
}

static int cmd_info(int argc, char **argv)
{
    scene sc;
    char err[SCENE_ERR_LEN];
    const char *path = NULL;
    bool json = false, vflags = false;
    int order = -1;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) {
            fputs(usage_info, stdout);
            return 0;
        } else if (!strcmp(argv[i], "--order")) {
            if (i + 1 >= argc || (order = parse_order(argv[i + 1])) < 0)
                return bad_arg("info", "--order: '%s' is not 'serial' or 'redblack'", i + 1 < argc ? argv[i + 1] : "");
            i++;
        } else if (!strcmp(argv[i], "--json")) {
            json = true;
        } else if (!strcmp(argv[i], "--vflags")) {
            vflags = true;
        } else if (argv[i][0] == '-') {
            return bad_arg("info", "unknown option '%s'", argv[i]);
        } else if (!path) {
            path = argv[i];
        } else {
            return bad_arg("info", "unexpected argument '%s'", argv[i]);
        }
    }
    if (!path) return bad_arg("info", "%s", "needs SCENE");
    if (!load(path, &sc, order)) return EXIT_BAD_INPUT;
    hw_params hp;
    hw_params_of(&sc, &hp);
    const char *why = hw_check(&sc, err, sizeof err);
    char text[2048];
    hw_timing_text(&hp, text, (int)sizeof text);
    if (vflags) {
        const char *sep = "";
#define STRAND_VFLAG(NAME, name, sw, ...) printf(sw ? "%s-G%s=1'b%d" : "%s-G%s=%d", sep, #NAME, hp.name), sep = " ";
        STRAND_PARAMS(STRAND_VFLAG)
#undef STRAND_VFLAG
        printf("\n");
    } else if (json) {
        printf("{\"scene\": \"%s\", \"rtl\": %s, ", sc.path, why ? "false" : "true");
        if (why) {
            printf("\"why\": \"");
            for (const char *q = why; *q; q++) printf(*q == '"' || *q == '\\' ? "\\%c" : "%c", *q);
            printf("\", ");
        }
        const char *sep = "";
        printf("\"params\": {");
#define STRAND_JSON(NAME, name, ...) printf("%s\"%s\": %d", sep, #NAME, hp.name), sep = ", ";
        STRAND_PARAMS(STRAND_JSON)
        printf("}, \"derived\": {");
        sep = "";
        STRAND_DERIVED(STRAND_JSON)
#undef STRAND_JSON
        printf("}, \"timing\": {\"toward_latency\": %ld, \"spring_latency\": %ld, \"constraint_pass\": %ld, "
               "\"spring_pass\": %ld, \"cycles_per_frame\": %ld, \"stream_slot_bound\": %d}}\n",
               hw_toward_latency(&hp), hw_spring_latency(&hp), hw_constraint_pass(&hp), hw_spring_pass(&hp),
               hw_cycles_per_frame(&hp), hw_stream_slot_bound(&hp) ? 1 : 0);
    } else {
        printf("%s: %s\n", sc.path, why ? why : "the RTL runs this scene with this build of strand_core:");
#define STRAND_TEXT(NAME, name, ...) printf("  %-15s %d\n", #NAME, hp.name);
        STRAND_PARAMS(STRAND_TEXT)
        printf("derived:\n");
        STRAND_DERIVED(STRAND_TEXT)
#undef STRAND_TEXT
        printf("cycles (model/timing.c):\n%s", text);
    }
    scene_free(&sc);
    return 0;
}

/* ---- set ---- */

static const char *usage_set =
    "usage: strand set SCENE OUT SECTION.KEY=VALUE...\n"
    "Write OUT: SCENE with each key set, its line replaced or added at the end of its\n"
    "section (a missing section at the end of the file), comments and layout kept. OUT\n"
    "must be a valid scene: else 'file:line: message' or 'SECTION.KEY=VALUE: message'\n"
    "on stderr, exit 2, and nothing written. The scripts derive their scenes this way.\n"
    "  e.g. strand set sim/scenes/pendulum.scene /tmp/p.scene time.substeps=16 constraints.rule=centred\n";

static int cmd_set(int argc, char **argv)
{
    char err[SCENE_ERR_LEN];
    for (int i = 1; i < argc; i++)
        if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) {
            fputs(usage_set, stdout);
            return 0;
        }
    if (argc < 3) return bad_arg("set", "%s", "needs SCENE and OUT");
    if (!scene_edit(argv[1], argv[2], argc - 3, (const char *const *)argv + 3, err)) {
        fprintf(stderr, "%s\n", err);
        return EXIT_BAD_INPUT;
    }
    return 0;
}

int main(int argc, char **argv)
{
    if (argc < 2 || !strcmp(argv[1], "--help") || !strcmp(argv[1], "-h") || !strcmp(argv[1], "help")) {
        fputs(usage_main, argc < 2 ? stderr : stdout);
        return argc < 2 ? EXIT_BAD_INPUT : 0;
    }
    if (!strcmp(argv[1], "check")) return cmd_check(argc - 1, argv + 1);
    if (!strcmp(argv[1], "run")) return cmd_run(argc - 1, argv + 1);
    if (!strcmp(argv[1], "compare")) return cmd_compare(argc - 1, argv + 1);
    if (!strcmp(argv[1], "hwgen")) return cmd_hwgen(argc - 1, argv + 1);
    if (!strcmp(argv[1], "info")) return cmd_info(argc - 1, argv + 1);
    if (!strcmp(argv[1], "board")) return cmd_board(argc - 1, argv + 1);
    if (!strcmp(argv[1], "set")) return cmd_set(argc - 1, argv + 1);
    fprintf(stderr, "strand: unknown command '%s'\n%s", argv[1], usage_main);
    return EXIT_BAD_INPUT;
}
