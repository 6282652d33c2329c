/*
 * test_physics.c - invariants of the frame engine on the shipped scenes and on
 * small purpose-made ones, in both number types, and the CLI's contract.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmocka.h>

#include "engine.h"
#include "scene.h"
#include "sim.h"

static const char *const shipped[] = {"ref000_rope", "hanging_rope", "pendulum", "ref001_video1", "ref001_video2", "ref001_video3", "ref001_video4",
                                      "ref002_euler", "ref002_verlet", "ref002_verlet_springs", "ref004_chain"};
#define N_SHIPPED (sizeof shipped / sizeof *shipped)

static void load_shipped(scene *sc, const char *name)
{
    char path[512], err[SCENE_ERR_LEN];
    snprintf(path, sizeof path, "%s/sim/scenes/%s.scene", STRAND_ROOT, name);
    if (!scene_load(sc, path, err)) fail_msg("%s", err);
}

static void load_text(scene *sc, const char *text)
{
    char path[64], err[SCENE_ERR_LEN];
    FILE *f;
    snprintf(path, sizeof path, "/tmp/strand-physics-%d.scene", (int)getpid());
    f = fopen(path, "w");
    assert_non_null(f);
    fputs(text, f);
    fclose(f);
    if (!scene_load(sc, path, err)) fail_msg("%s", err);
    unlink(path);
}

static void test_pinned_nodes_never_move(void **state)
{
    (void)state;
    for (size_t s = 0; s < N_SHIPPED; s++) {
        scene sc;
        sim_fx fx;
        sim_dbl dbl;
        load_shipped(&sc, shipped[s]);
        assert_true(sim_fx_init(&fx, &sc, &sc.fmt));
        assert_true(sim_dbl_init(&dbl, &sc, NULL));
        fx_t (*start)[3] = malloc((size_t)sc.n_nodes * sizeof *start);
        memcpy(start, fx.pos, (size_t)sc.n_nodes * sizeof *start);
        for (int f = 0; f < 200; f++) {
            sim_fx_frame(&fx);
            sim_dbl_frame(&dbl);
            for (int i = 0; i < sc.n_nodes; i++) {
                if (!sc.pinned[i]) continue;
                for (int k = 0; k < 3; k++) {
                    if (fx.pos[i][k] != start[i][k]) fail_msg("%s: pinned node %d moved (fixed, frame %d)", shipped[s], i, f + 1);
                    if (dbl.pos[i][k] != sc.pos[i][k]) fail_msg("%s: pinned node %d moved (double, frame %d)", shipped[s], i, f + 1);
                }
            }
        }
        free(start);
        sim_fx_free(&fx);
        sim_dbl_free(&dbl);
        scene_free(&sc);
    }
}

/* The pairwise rule moves both ends by the same amount: the strut's midpoint stays, bit for bit. */
static void test_strut_keeps_its_centre(void **state)
{
    scene sc;
    sim_fx fx;
    uint64_t seed = 12345;
    (void)state;
    load_text(&sc, "[scene]\ndim = 3\n[time]\ndt = 0.01\n[graph]\nnode = 0 0 0\nnode = 30 0 0\nedge = 0 1 strut\n[constraints]\n");
    assert_true(sim_fx_init(&fx, &sc, &sc.fmt));
    for (int trial = 0; trial < 10000; trial++) {
        int64_t sum[3];
        for (int i = 0; i < 2; i++)
            for (int k = 0; k < 3; k++) {
                seed = seed * 6364136223846793005ull + 1442695040888963407ull;
                fx.pos[i][k] = (fx_t)((int64_t)(seed >> 40) - (1 << 23)) * 16; /* within +-2048 */
            }
        double before = 0, after = 0;
        for (int k = 0; k < 3; k++) {
            double d = fx_to_double(&fx.fmt, fx.pos[1][k] - fx.pos[0][k]);
            before += d * d;
            sum[k] = (int64_t)fx.pos[0][k] + fx.pos[1][k];
        }
        sim_fx_pair_edge(&fx, 0);
        for (int k = 0; k < 3; k++) {
            double d = fx_to_double(&fx.fmt, fx.pos[1][k] - fx.pos[0][k]);
            after += d * d;
            assert_int_equal((int64_t)fx.pos[0][k] + fx.pos[1][k], sum[k]);
        }
        /* the length is restored up to the ratio's quantum (2^-F) times the old length */
        assert_float_equal(sqrt(after), 30.0, sqrt(before) * ldexp(1.0, -fx.fmt.frac) + 1e-4);
    }
    sim_fx_free(&fx);
    scene_free(&sc);
}

static void test_no_node_below_the_ground(void **state)
{
    (void)state;
    for (int v = 1; v <= 4; v++) {
        char name[32];
        scene sc;
        sim_fx fx;
        sim_dbl dbl;
        snprintf(name, sizeof name, "ref001_video%d", v);
        load_shipped(&sc, name);
        assert_true(sim_fx_init(&fx, &sc, &sc.fmt));
        assert_true(sim_dbl_init(&dbl, &sc, NULL));
        int contacts = 0;
        for (int f = 0; f < sc.frames; f++) {
            sim_fx_frame(&fx);
            sim_dbl_frame(&dbl);
            for (int i = 0; i < sc.n_nodes; i++) {
                if (fx.pos[i][2] < fx.ground) fail_msg("%s frame %d: node %d below the ground (fixed)", name, f + 1, i);
                if (dbl.pos[i][2] < dbl.ground) fail_msg("%s frame %d: node %d below the ground (double)", name, f + 1, i);
                contacts += fx.pos[i][2] == fx.ground;
            }
        }
        assert_true(contacts > 0); /* the body did reach the ground */
        sim_fx_free(&fx);
        sim_dbl_free(&dbl);
        scene_free(&sc);
    }
}

/* All nodes on one point: every length is zero, every correction is skipped, nothing is garbage. */
static void test_coincident_nodes_stay_finite(void **state)
{
    static const char *const bodies[] = {
        "[time]\ndt = 0.01\n[chain]\nunits = 2\nnodes_per_unit = 4\nstart = 3 3\nstep = 0 0\nrest = 1\n[constraints]\nrule = centred\n",
        "[time]\ndt = 0.01\n[chain]\nunits = 2\nnodes_per_unit = 4\nstart = 3 3\nstep = 0 0\nrest = 1\n[constraints]\nrule = pairwise\n",
        "[time]\ndt = 0.01\n[chain]\nunits = 2\nnodes_per_unit = 4\nstart = 3 3\nstep = 0 0\nrest = 1\n[springs]\nks = 50\nkd = 1\n",
    };
    (void)state;
    for (size_t b = 0; b < 3; b++) {
        scene sc;
        load_text(&sc, bodies[b]);
        for (int kind = 0; kind < 2; kind++) {
            runner r;
            double (*pos)[3] = calloc((size_t)sc.n_nodes, sizeof *pos);
            assert_true(runner_init(&r, &sc, (number_kind)kind, &sc.fmt));
            for (int f = 0; f < 20; f++) runner_frame(&r);
            runner_positions(&r, pos);
            for (int i = 0; i < sc.n_nodes; i++) {
                assert_true(isfinite(pos[i][0]) && isfinite(pos[i][1]));
                assert_float_equal(pos[i][0], 3.0, 0);
                assert_float_equal(pos[i][1], 3.0, 0);
            }
            assert_true(runner_skipped(&r) > 0);
            runner_free(&r);
            free(pos);
        }
        scene_free(&sc);
    }
}

/* The tolerance docs/model.md states for the default rope. */
#define ROPE_RMS_TOLERANCE 0.05 /* rest lengths */
#define ROPE_MAX_TOLERANCE 0.25

static void test_fixed_agrees_with_double_on_the_default_rope(void **state)
{
    scene sc;
    runner fx, dbl;
    double sum2 = 0, worst = 0;
    long n = 0;
    (void)state;
    load_shipped(&sc, "ref000_rope");
    double (*pf)[3] = calloc((size_t)sc.n_nodes, sizeof *pf), (*pd)[3] = calloc((size_t)sc.n_nodes, sizeof *pd);
    assert_true(runner_init(&fx, &sc, NUMBER_FIXED, &sc.fmt) && runner_init(&dbl, &sc, NUMBER_DOUBLE, NULL));
    for (int f = 0; f < sc.frames; f++) {
        runner_frame(&fx);
        runner_frame(&dbl);
        runner_positions(&fx, pf);
        runner_positions(&dbl, pd);
        for (int i = 0; i < sc.n_nodes; i++) {
            double e = hypot(pf[i][0] - pd[i][0], pf[i][1] - pd[i][1]) / sc.chain_rest;
            sum2 += e * e;
            n++;
            worst = fmax(worst, e);
        }
    }
    assert_true(sqrt(sum2 / n) < ROPE_RMS_TOLERANCE);
    assert_true(worst < ROPE_MAX_TOLERANCE);
    assert_true(worst > 0); /* they are different computations */
    runner_free(&fx);
    runner_free(&dbl);
    free(pf);
    free(pd);
    scene_free(&sc);
}

/* Reference 002: explicit Euler gains energy without bound; Verlet with the same springs does not. */
static void test_euler_diverges_verlet_stays_bounded(void **state)
{
    (void)state;
    for (int kind = 0; kind < 2; kind++) {
        scene eu, ve, vc;
        run_stats se, sv, sc_;
        load_shipped(&eu, "ref002_euler");
        load_shipped(&ve, "ref002_verlet_springs");
        load_shipped(&vc, "ref002_verlet");
        assert_true(run_scene(&eu, (number_kind)kind, &eu.fmt, 120, NULL, NULL, &se));
        assert_true(run_scene(&ve, (number_kind)kind, &ve.fmt, 300, NULL, NULL, &sv));
        assert_true(run_scene(&vc, (number_kind)kind, &vc.fmt, 300, NULL, NULL, &sc_));
        /* Euler: the rope tears itself apart (stretch beyond 10 rest lengths) */
        assert_true(!se.finite || se.max_stretch > 1000.0);
        /* Verlet: finite, stretch bounded, and no energy gained from nowhere */
        assert_true(sv.finite && sv.max_stretch < 20.0 && sv.energy <= sv.energy0 + 1e-6 * sv.ke_max);
        assert_true(sc_.finite && sc_.max_stretch < 1.0 && sc_.energy <= sc_.energy0);
        scene_free(&eu);
        scene_free(&ve);
        scene_free(&vc);
    }
}

#define MOUSE_BODY "[time]\ndt = 1\n[chain]\nunits = 1\nnodes_per_unit = 5\nstart = 0 0\nstep = 10 0\n[mouse]\nbox = 4 4\n"

static void test_mouse_impulse(void **state)
{
    scene sc;
    sim_fx fx;
    (void)state;
    load_text(&sc, MOUSE_BODY "impulse = 2\nevent = 0 21 1 1\n");
    assert_true(sim_fx_init(&fx, &sc, &sc.fmt));
    sim_fx_frame(&fx);
    /* node 2 at x=20 is in touch; mouse.x (21) is not below x- (20): x- <- x - a, so it moves +a */
    assert_int_equal(fx.pos[2][0] - fx.prev[2][0], 2 * fx_one(&fx.fmt));
    for (int i = 0; i < 5; i++)
        if (i != 2) assert_int_equal(fx.pos[i][0] - fx.prev[i][0], 0);
    sim_fx_frame(&fx);
    assert_int_equal(fx.pos[2][0], fx_from_double(&fx.fmt, 22));
    sim_fx_free(&fx);
    scene_free(&sc);
}

static void test_mouse_grab(void **state)
{
    scene sc;
    sim_dbl s;
    (void)state;
    load_text(&sc, MOUSE_BODY "mode = grab\nevent = 0 19 1 1\nevent = 1 50 50 1\nevent = 2 50 50 0\n");
    assert_true(sim_dbl_init(&s, &sc, NULL));
    sim_dbl_frame(&s); /* press near node 2 (x=20): it is taken to the pointer */
    assert_int_equal(s.grabbed, 2);
    assert_float_equal(s.pos[2][0], 19, 0);
    sim_dbl_frame(&s); /* held: it follows the pointer, far outside the box */
    assert_float_equal(s.pos[2][0], 50, 0);
    assert_float_equal(s.pos[2][1], 50, 0);
    sim_dbl_frame(&s); /* released: it keeps the pointer's last motion, 19 -> 50 */
    assert_int_equal(s.grabbed, -1);
    assert_float_equal(s.pos[2][0], 81, 0);
    assert_float_equal(s.pos[2][1], 99, 0);
    sim_dbl_free(&s);
    scene_free(&sc);
}

/* A body at rest with no effects named stays exactly where it is. */
static void test_nothing_named_nothing_moves(void **state)
{
    scene sc;
    runner r;
    double pos[6][3];
    (void)state;
    load_text(&sc, "[time]\ndt = 0.1\n[chain]\nunits = 2\nnodes_per_unit = 3\nstart = 1 2\nstep = 0.5 0.25\n");
    for (int kind = 0; kind < 2; kind++) {
        assert_true(runner_init(&r, &sc, (number_kind)kind, &sc.fmt));
        for (int f = 0; f < 100; f++) runner_frame(&r);
        runner_positions(&r, pos);
        for (int i = 0; i < 6; i++) {
            assert_float_equal(pos[i][0], sc.pos[i][0], 0);
            assert_float_equal(pos[i][1], sc.pos[i][1], 0);
        }
        runner_free(&r);
    }
    scene_free(&sc);
}

/* Ground contact: reversed normal velocity, tangential velocity scaled by u. */
static void test_ground_bounce_and_friction(void **state)
{
    scene sc;
    sim_dbl s;
    (void)state;
    load_text(&sc, "[time]\ndt = 1\n[graph]\nnode = 0 1\nvelocity = 4 -3\n[ground]\nnormal = +y\nlevel = 0\nradius = 0.5\nfriction = 0.75\n");
    assert_true(sim_dbl_init(&s, &sc, NULL));
    sim_dbl_frame(&s); /* y: 1 - 3 = -2 < 0.5: put on 0.5, moving up at 3; x: 4 * 0.75 */
    assert_float_equal(s.pos[0][1], 0.5, 1e-12);
    assert_float_equal(s.pos[0][1] - s.prev[0][1], 3, 1e-12);
    assert_float_equal(s.pos[0][0] - s.prev[0][0], 3, 1e-12);
    sim_dbl_free(&s);
    scene_free(&sc);
}

/* Wind (the effects table's first row): one step by hand, then the node's velocity relaxes to
   the wind's, v_n = w h + (v_0 - w h)(1 - c h)^n, a geometric series with no gravity. */
static void test_wind_drag_relaxes_to_the_wind(void **state)
{
    scene sc;
    sim_dbl s;
    (void)state;
    load_text(&sc, "[time]\ndt = 0.5\n[graph]\nnode = 0 0\nvelocity = 2 0\n[wind]\nvelocity = 6 -4\ndrag = 0.4\n");
    assert_true(sc.en_wind);
    assert_true(sim_dbl_init(&s, &sc, NULL));
    assert_float_equal(s.drag, 0.2, 1e-15); /* c h */
    assert_float_equal(s.wind[0], 3, 1e-15); /* w h */
    assert_float_equal(s.wind[1], -2, 1e-15);
    sim_dbl_frame(&s); /* v = 1 - 0.2 (1 - 3) = 1.4; y: 0 - 0.2 (0 + 2) = -0.4 */
    assert_float_equal(s.pos[0][0], 1.4, 1e-12);
    assert_float_equal(s.pos[0][1], -0.4, 1e-12);
    for (int n = 1; n < 60; n++) sim_dbl_frame(&s);
    double vx = s.pos[0][0] - s.prev[0][0], vy = s.pos[0][1] - s.prev[0][1];
    assert_float_equal(vx, 3 + (1 - 3) * pow(0.8, 60), 1e-9);
    assert_float_equal(vy, -2 + (0 + 2) * pow(0.8, 60), 1e-9);
    sim_dbl_free(&s);
    scene_free(&sc);
}

/* ---- the CLI ---- */

static int run_cli(const char *args)
{
    char cmd[2200];
    snprintf(cmd, sizeof cmd, "%s %s >/dev/null 2>/tmp/strand-cli-%d.err", STRAND_BIN, args, (int)getpid());
    int status = system(cmd);
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

static long count_lines(const char *path)
{
    FILE *f = fopen(path, "r");
    long n = 0;
    int c;
    if (!f) return -1;
    while ((c = fgetc(f)) != EOF) n += c == '\n';
    fclose(f);
    return n;
}

/* Fixed-point Verlet is time-reversible: x+ = 2x - x- + a(x) h^2 run from (x, x+) gives x-
   back, in integers exactly, when a depends on the position alone (gravity, springs without a
   damper). Run forward, swap the current and previous positions, run as long again, swap
   back: the start, bit for bit. A damper, the ground or a constraint projection breaks it. */
static void run_back_and_forth(const char *text, int frames)
{
    scene sc;
    runner r;
    fx_t (*pos0)[3], (*prev0)[3];
    load_text(&sc, text);
    assert_true(runner_init(&r, &sc, NUMBER_FIXED, &sc.fmt));
    pos0 = malloc(sizeof *pos0 * (size_t)r.fx.n);
    prev0 = malloc(sizeof *prev0 * (size_t)r.fx.n);
    assert_true(pos0 && prev0);
    memcpy(pos0, r.fx.pos, sizeof *pos0 * (size_t)r.fx.n);
    memcpy(prev0, r.fx.prev, sizeof *prev0 * (size_t)r.fx.n);
    for (int pass = 0; pass < 2; pass++) {
        for (int f = 0; f < frames; f++) runner_frame(&r);
        if (pass == 0) assert_int_not_equal(memcmp(pos0, r.fx.pos, sizeof *pos0 * (size_t)r.fx.n), 0); /* it moved */
        for (int i = 0; i < r.fx.n; i++)
            for (int k = 0; k < 3; k++) {
                fx_t t = r.fx.pos[i][k];
                r.fx.pos[i][k] = r.fx.prev[i][k];
                r.fx.prev[i][k] = t;
            }
    }
    for (int i = 0; i < r.fx.n; i++)
        for (int k = 0; k < 3; k++) {
            if (r.fx.pos[i][k] != pos0[i][k] || r.fx.prev[i][k] != prev0[i][k])
                fail_msg("node %d axis %d: back at %d / %d, started at %d / %d", i, k, r.fx.pos[i][k], r.fx.prev[i][k], pos0[i][k],
                         prev0[i][k]);
        }
    free(pos0);
    free(prev0);
    runner_free(&r);
    scene_free(&sc);
}

static void test_verlet_is_time_reversible(void **state)
{
    (void)state;
    /* free bodies in 3D under gravity, thrown */
    run_back_and_forth("[scene]\ndim = 3\n[time]\ndt = 1\nsubsteps = 4\n[graph]\nnode = 0 0 0\nnode = 10 -3 2.5\n"
                       "node = -7 1 4\nvelocity = 0.3 0.7 -0.2\nnode_prev_offset = 1 0.05 0 -0.01\n[gravity]\naccel = 0 -0.01 0.002\n",
                       300);
    /* a spring chain without a damper, stretched and falling */
    run_back_and_forth("[time]\ndt = 1\nsubsteps = 2\n[chain]\nunits = 2\nnodes_per_unit = 4\nstart = 0 0\nstep = 6 1\nrest = 5\n"
                       "[springs]\nks = 0.05\n[gravity]\naccel = 0 -0.02\n",
                       200);
}

/* projection = previous (SHAKE) keeps the undamped pendulum's energy over 10^5 frames
   (60 frames/s, 8 substeps, 10 degrees) within 1 % in Q16.16 and 0.1 % in double, where
   projection along the current direction loses nearly all of it. */
static void test_previous_projection_keeps_energy(void **state)
{
    scene sc;
    run_stats cur, prev, prev_d;
    (void)state;
    load_shipped(&sc, "pendulum_undamped");
    assert_int_equal(sc.frames, 100000);
    assert_true(run_scene(&sc, NUMBER_FIXED, &sc.fmt, sc.frames, NULL, NULL, &cur));
    sc.projection = PROJECTION_PREVIOUS;
    assert_true(run_scene(&sc, NUMBER_FIXED, &sc.fmt, sc.frames, NULL, NULL, &prev));
    assert_true(run_scene(&sc, NUMBER_DOUBLE, NULL, sc.frames, NULL, NULL, &prev_d));
    if (!(cur.drift_pct < -90) || !(fabs(prev.drift_pct) <= 1) || !(fabs(prev_d.drift_pct) <= 0.1))
        fail_msg("energy drift over 10^5 frames: current %.3f %%, previous %.3f %% (fixed), %.4f %% (double)", cur.drift_pct,
                 prev.drift_pct, prev_d.drift_pct);
    scene_free(&sc);
}

static void test_cli_contract(void **state)
{
    char args[1024], out[128], dir[128], bad[128];
    struct stat st;
    (void)state;
    snprintf(out, sizeof out, "/tmp/strand-cli-%d.csv", (int)getpid());
    snprintf(dir, sizeof dir, "/tmp/strand-cli-%d.png", (int)getpid());
    snprintf(bad, sizeof bad, "/tmp/strand-cli-%d.scene", (int)getpid());
    unlink(out);

    assert_int_equal(run_cli(""), 2);
    assert_int_equal(run_cli("frobnicate x"), 2);
    assert_int_equal(run_cli("run"), 2);
    assert_int_equal(run_cli("run --frames -3 " STRAND_ROOT "/sim/scenes/pendulum.scene"), 2);
    assert_int_equal(run_cli("run --format float " STRAND_ROOT "/sim/scenes/pendulum.scene"), 2);
    assert_int_equal(run_cli("run --bogus " STRAND_ROOT "/sim/scenes/pendulum.scene"), 2);
    assert_int_equal(run_cli("run --help"), 0);
    assert_int_equal(run_cli("check --help"), 0);
    assert_int_equal(run_cli("compare --help"), 0);

    /* a bad scene: exit 2 and nothing written */
    FILE *f = fopen(bad, "w");
    fputs("[time]\ndt = 1\n[chain]\nunits = 2\n", f);
    fclose(f);
    snprintf(args, sizeof args, "run %s --csv %s", bad, out);
    assert_int_equal(run_cli(args), 2);
    assert_int_not_equal(stat(out, &st), 0);
    /* a bad argument after a good scene: same */
    snprintf(args, sizeof args, "run " STRAND_ROOT "/sim/scenes/pendulum.scene --csv %s --frames x", out);
    assert_int_equal(run_cli(args), 2);
    assert_int_not_equal(stat(out, &st), 0);

    /* a good run writes one CSV line per node per frame, and the pictures */
    snprintf(args, sizeof args, "run " STRAND_ROOT "/sim/scenes/ref000_rope.scene --frames 7 --csv %s --png %s", out, dir);
    assert_int_equal(run_cli(args), 0);
    assert_int_equal(count_lines(out), 1 + 7 * 20);
    snprintf(args, sizeof args, "%s/frame_00007.png", dir);
    assert_int_equal(stat(args, &st), 0);
    assert_true(st.st_size > 100);
    snprintf(args, sizeof args, "rm -rf %s %s %s", dir, out, bad);
    assert_int_equal(system(args), 0);

    /* --hex needs fixed point */
    snprintf(args, sizeof args, "run " STRAND_ROOT "/sim/scenes/pendulum.scene --format double --hex %s", out);
    assert_int_equal(run_cli(args), 2);
    assert_int_equal(run_cli("check " STRAND_ROOT "/sim/scenes/ref001_video1.scene"), 0);
    assert_int_equal(run_cli("compare --frames 10 " STRAND_ROOT "/sim/scenes/ref001_video1.scene"), 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_pinned_nodes_never_move),
        cmocka_unit_test(test_strut_keeps_its_centre),
        cmocka_unit_test(test_no_node_below_the_ground),
        cmocka_unit_test(test_coincident_nodes_stay_finite),
        cmocka_unit_test(test_fixed_agrees_with_double_on_the_default_rope),
        cmocka_unit_test(test_euler_diverges_verlet_stays_bounded),
        cmocka_unit_test(test_mouse_impulse),
        cmocka_unit_test(test_mouse_grab),
        cmocka_unit_test(test_nothing_named_nothing_moves),
        cmocka_unit_test(test_ground_bounce_and_friction),
        cmocka_unit_test(test_wind_drag_relaxes_to_the_wind),
        cmocka_unit_test(test_verlet_is_time_reversible), cmocka_unit_test(test_previous_projection_keeps_energy), cmocka_unit_test(test_cli_contract),
    };
    return cmocka_run_group_tests_name("physics and CLI", tests, NULL, NULL);
}
