/*
 * test_scene.c - every validation error names the right line, and the shipped
 * scenes load. Each case writes a small scene to a temporary file.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <cmocka.h>

#include "scene.h"

static const char *write_scene(const char *text)
{
    static char path[64];
    FILE *f;
    snprintf(path, sizeof path, "/tmp/strand-test-%d.scene", (int)getpid());
    f = fopen(path, "w");
    assert_non_null(f);
    fputs(text, f);
    fclose(f);
    return path;
}

/* Loading `text` must fail at `line` with a message containing `words`. */
static void expect_error(const char *text, int line, const char *words)
{
    scene sc;
    char err[SCENE_ERR_LEN], prefix[128];
    const char *path = write_scene(text);
    bool ok = scene_load(&sc, path, err);
    snprintf(prefix, sizeof prefix, "%s:%d: ", path, line);
    if (ok) fail_msg("accepted a bad scene, expected line %d: %s\n%s", line, words, text);
    if (strncmp(err, prefix, strlen(prefix)) != 0 || !strstr(err, words))
        fail_msg("got '%s'\nexpected '%s...%s...'", err, prefix, words);
    unlink(path);
}

#define CHAIN "[chain]\nunits = 2\nnodes_per_unit = 3\nstart = 0 0\nstep = 1 0\n" /* lines +1..+5 */
#define TIME "[time]\ndt = 0.01\n"                                                 /* lines +1..+2 */

static void test_syntax_and_keys(void **state)
{
    (void)state;
    expect_error(TIME "[bogus]\nx = 1\n", 3, "unknown section [bogus]");
    expect_error(TIME "[empty_unknown]\n", 3, "unknown section [empty_unknown]");
    expect_error(TIME "colour = red\n", 3, "unknown key 'colour' in [time]");
    expect_error(TIME "frames =\n", 3, "frames: missing value");
    expect_error(TIME "frames = 12x\n", 3, "'12x' is not a whole number");
    expect_error("[time]\ndt = fast\n", 2, "'fast' is not a decimal number");
    expect_error(TIME "substeps = 0\n", 3, "out of range");
    expect_error(TIME "dt = 0.02\n", 3, "duplicate key (first given on line 2)");
    expect_error(TIME "this line is not ini\n", 3, "syntax error");
    expect_error(TIME "[chain\n", 3, "syntax error");
    expect_error(TIME "[time]\n", 3, "section [time] appears twice");
    expect_error(TIME "integrator = rk4\n", 3, "'rk4' is not one of: verlet, euler");
    {
        char text[600];
        snprintf(text, sizeof text, TIME "; %0300d\n", 0);
        expect_error(text, 3, "longer than");
        /* 200 characters do not pass: sim/scenes/README.md says 199 */
        snprintf(text, sizeof text, TIME "; %0198d\n", 0);
        expect_error(text, 3, "longer than 199 characters");
    }
    /* numbers are decimal: no hexadecimal, inf or nan (strtod would take them) */
    expect_error("[time]\ndt = 0x10\n", 2, "dt: '0x10' is not a decimal number");
    expect_error("[time]\ndt = inf\n", 2, "'inf' is not a decimal number");
    expect_error("[time]\ndt = nan\n", 2, "'nan' is not a decimal number");
    expect_error("[time]\ndt = 1e\n", 2, "'1e' is not a decimal number");
    expect_error("[time]\ndt = .\n", 2, "'.' is not a decimal number");
    expect_error(TIME CHAIN "[mouse]\nbox = 5 5\nimpulse = 1\nevent = 0x5 0 0 1\n", 11, "'0x5' is not a decimal number");
    expect_error(TIME CHAIN "[gravity]\naccel = 0 0x1p3\n", 9, "'0x1p3' is not a decimal number");
    /* a section header is the whole line, but for blanks and a comment */
    expect_error(TIME "[chain]x\n", 3, "unexpected text after [chain]");
    expect_error(TIME "[chain] [gravity]\n", 3, "unexpected text after [chain]");
}

/* What the format accepts: the longest line, decimal forms, a comment after a header. */
static void test_accepted_forms(void **state)
{
    scene sc;
    char err[SCENE_ERR_LEN], text[600];
    (void)state;
    snprintf(text, sizeof text, "[time] ; the clock\ndt = +1.e-2\n; %0197d\n[chain]\t# two units\nunits = 2\n"
             "nodes_per_unit = 3\nstart = -.5 0\nstep = 1E0 +0.\n", 0);
    if (!scene_load(&sc, write_scene(text), err)) fail_msg("rejected a good scene: %s", err);
    assert_float_equal(sc.dt, 0.01, 1e-15);
    assert_float_equal(sc.pos[0][0], -0.5, 1e-15);
    assert_float_equal(sc.pos[1][0], 0.5, 1e-15);
    scene_free(&sc);
}

static void test_required_and_contradictions(void **state)
{
    (void)state;
    expect_error(CHAIN, 1, "no [time] section");
    expect_error("[time]\nframes = 3\n" CHAIN, 1, "[time] needs 'dt'");
    expect_error(TIME, 1, "no body");
    expect_error(TIME CHAIN "[graph]\nnode = 0 0\n", 8, "one body");
    expect_error(TIME "[chain]\nunits = 2\nnodes_per_unit = 3\nstep = 1 0\n", 3, "needs 'start'");
    expect_error(TIME "[chain]\nunits = 2\nnodes_per_unit = 3\nstart = 0 0\n", 3, "needs 'step' or 'end'");
    expect_error(TIME CHAIN "end = 5 0\n", 8, "'step' or 'end', not both");
    expect_error(TIME CHAIN "nodes = 7\n", 8, "nodes = 7 but units x nodes_per_unit = 2 x 3 = 6");
    expect_error(TIME CHAIN "pinned = 0 6\n", 8, "node 6 does not exist");
    expect_error(TIME "[chain]\nunits = 2\nnodes_per_unit = 3\nstart = 0 0 0\nstep = 1 0\n", 6, "expected 2 numbers for a 2D scene");
    expect_error(TIME CHAIN "[gravity]\n", 8, "[gravity] needs 'accel'");
    expect_error(TIME CHAIN "[mouse]\nbox = 5 5\n", 8, "needs 'impulse'");
    expect_error(TIME CHAIN "[mouse]\nbox = 5 -5\nimpulse = 1\n", 9, "positive");
    expect_error(TIME CHAIN "[mouse]\nbox = 5 5\nimpulse = 1\nevent = 5 0 0 1\nevent = 4 0 0 0\n", 12, "comes before");
    expect_error(TIME CHAIN "[mouse]\nbox = 5 5\nimpulse = 1\nevent = 5 0 0 2\n", 11, "button must be 0");
    expect_error(TIME CHAIN "[mouse]\nbox = 5 5\nimpulse = 1\nevent = 5 0 0 0 1\n", 11, "expected frame, 2 coordinates");
    expect_error(TIME CHAIN "[springs]\nkd = 1\n", 8, "needs 'ks'");
    expect_error(TIME CHAIN "[ground]\nlevel = 0\n", 8, "needs 'normal'");
    expect_error(TIME CHAIN "[ground]\nnormal = +z\n", 9, "no z axis");
    expect_error("[time]\ndt = 0.01\nintegrator = euler\n" CHAIN "[constraints]\n", 3, "euler cannot project");
    expect_error(TIME "[chain]\nunits = 2\nnodes_per_unit = 3\nstart = 0 0\nstep = 0 0\n[constraints]\n", 3, "give 'rest'");
}

/* The effects table's keys (scripts/gen_effects.py): wind's section, its constant's range, Euler;
   damping's key in [time]. */
static void test_table_effects(void **state)
{
    static const struct {
        const char *text;
        int line;
        const char *words;
    } bad[] = {
        {TIME CHAIN "[wind]\nvelocity = 1 0\n", 8, "[wind] needs 'drag'"},
        {TIME CHAIN "[wind]\ndrag = 1\nvelocity = 1 0 0\n", 10, "expected 2 numbers for a 2D scene"},
        {TIME CHAIN "[wind]\ndrag = 200\n", 9, "drag: c h = 2 is outside"}, /* h = 0.01 */
        {TIME CHAIN "[wind]\ndrag = -1\n", 9, "drag"},
        {TIME CHAIN "[wind]\ndrag = 1\ngust = 2\n", 10, "unknown key 'gust' in [wind]"},
        {"[time]\ndt = 0.01\nintegrator = euler\n" CHAIN "[wind]\ndrag = 1\n", 3, "euler does not support [wind]"},
        {"[time]\ndt = 0.01\nintegrator = euler\ndamping = 0.1\n" CHAIN, 4, "damping: Verlet damping has no meaning for euler"},
        {"[time]\ndt = 0.01\ndamping = 1\n" CHAIN, 3, "damping"}, /* d < 1 */
    };
    (void)state;
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) expect_error(bad[i].text, bad[i].line, bad[i].words);
    scene sc;
    char err[SCENE_ERR_LEN];
    const char *path = write_scene(TIME CHAIN "[wind]\ndrag = 1\n");
    assert_true(scene_load(&sc, path, err));
    assert_true(sc.en_wind);
    assert_true(sc.wind_velocity[0] == 0 && sc.wind_velocity[1] == 0); /* still air by default */
    scene_free(&sc);
    unlink(path);
}

static void test_graph_errors(void **state)
{
    (void)state;
#define G TIME "[graph]\nnode = 0 0\nnode = 1 0\nnode = 0 1\n" /* nodes at lines 4..6 */
    expect_error(G "edge = 0 3 rod\n[constraints]\n", 7, "node 3 does not exist");
    expect_error(G "edge = 1 1 rod\n", 7, "both ends are node 1");
    expect_error(G "edge = 0 1 rope\n", 7, "'rope' is not one of: rod, strut, spring");
    expect_error(G "edge = 0 1\n", 7, "expected 'A B KIND [REST]'");
    expect_error(G "edge = 0 1 rod\n", 7, "needs the [constraints] effect");
    expect_error(G "edge = 0 1 spring\n", 7, "needs the [springs] effect");
    expect_error(G "units = 2\n", 7, "lists 3 nodes but units x nodes_per_unit");
    expect_error(G "[constraints]\nrule = centred\n", 8, "a graph uses 'pairwise'");
    expect_error(TIME "[graph]\nnode = 0 0\nnode = 0 0\nedge = 0 1 rod\n[constraints]\n", 6, "start on one point");
    expect_error(G "node_prev_offset = 9 1 1\n", 7, "node 9 does not exist");
    expect_error(TIME "[graph]\nscale = 2\n", 3, "lists no 'node'");
#undef G
}

static void test_format_errors(void **state)
{
    (void)state;
    expect_error("[format]\nwidth = 16\nfrac = 15\n" TIME CHAIN, 3, "fraction bits must be 1..width-2");
    expect_error("[format]\nwidth = 16\nfrac = 8\nsqrt_bits = 16\n" TIME CHAIN, 4, "sqrt_bits must be 1..width-1");
    expect_error("[format]\nwidth = 16\n" TIME CHAIN, 2, "fraction bits must be 1..width-2 (width = 16, frac = 16)");
    expect_error("[format]\nwidth = 40\n" TIME CHAIN, 2, "out of range");
    expect_error("[format]\nwidth = 18\nfrac = 8\n" TIME "[chain]\nunits = 1\nnodes_per_unit = 2\nstart = 600 0\nstep = 1 0\n", 9,
                 "does not fit Q10.8");
    expect_error("[format]\nwidth = 18\nfrac = 8\n" TIME CHAIN "[mouse]\nbox = 5 5\nimpulse = 1\nevent = 0 900 0 1\n", 14,
                 "a mouse position = 900 does not fit");
    /* the same scene in double is fine */
    scene sc;
    char err[SCENE_ERR_LEN];
    assert_true(scene_load(&sc, write_scene("[format]\nnumber = double\n" TIME "[chain]\nunits = 1\nnodes_per_unit = 2\nstart = 1e6 0\nstep = 1 0\n"), err));
    scene_free(&sc);
}

/* A NUL byte is rejected at its line, wherever it is (fgets and strlen cannot see past one). */
static void test_nul_byte(void **state)
{
    static const char text[] = "[time]\n; a comment\0dt = 1\n[chain]\n";
    scene sc;
    char err[SCENE_ERR_LEN], prefix[128];
    const char *path = write_scene("");
    FILE *f = fopen(path, "wb");
    (void)state;
    assert_non_null(f);
    fwrite(text, 1, sizeof text - 1, f);
    fclose(f);
    assert_false(scene_load(&sc, path, err));
    snprintf(prefix, sizeof prefix, "%s:2: ", path);
    assert_non_null(strstr(err, prefix));
    assert_non_null(strstr(err, "NUL byte"));
    unlink(path);
}

static void test_missing_file(void **state)
{
    scene sc;
    char err[SCENE_ERR_LEN];
    (void)state;
    assert_false(scene_load(&sc, "/nonexistent/x.scene", err));
    assert_non_null(strstr(err, "/nonexistent/x.scene:0: cannot open"));
}

static void test_chain_layout_and_defaults(void **state)
{
    scene sc;
    char err[SCENE_ERR_LEN];
    (void)state;
    assert_true(scene_load(&sc, write_scene(TIME "[chain]\nunits = 2\nnodes_per_unit = 3\nstart = 1 2\nend = 11 2\npinned = 0\n[constraints]\n[springs]\nks = 5\n"), err));
    assert_int_equal(sc.n_nodes, 6);
    assert_int_equal(sc.n_edges, 10); /* 5 rods and 5 springs */
    assert_true(sc.en_constraints && sc.en_springs && !sc.en_gravity && !sc.en_mouse && !sc.en_ground);
    assert_float_equal(sc.pos[5][0], 11, 1e-12);
    assert_float_equal(sc.chain_rest, 2, 1e-12);
    assert_true(sc.pinned[0] && !sc.pinned[1]);
    assert_int_equal(sc.fmt.width, 32);
    assert_int_equal(sc.fmt.frac, 16);
    assert_int_equal(sc.fmt.sqrt_bits, 31);
    scene_free(&sc);
}

/* order = redblack: a chain's links even then odd, a graph's edges by a greedy colouring,
   springs untouched; serial keeps the scene's order; a bad value names its line. */
static void test_constraint_order(void **state)
{
    scene sc;
    char err[SCENE_ERR_LEN];
    (void)state;
    expect_error(TIME CHAIN "[constraints]\norder = random\n", 9, "'random' is not one of: serial, redblack");
    assert_true(scene_load(&sc, write_scene(TIME CHAIN "[constraints]\nrule = pairwise\norder = redblack\n[springs]\nks = 1\n"), err));
    assert_int_equal(sc.order, ORDER_REDBLACK);
    assert_int_equal(sc.n_colours, 2);
    assert_int_equal(sc.n_edges, 10);
    static const int links[5] = {0, 2, 4, 1, 3}; /* link i joins nodes i and i + 1 */
    for (int e = 0; e < 5; e++) {
        assert_int_equal(sc.edges[e].a, links[e]);
        assert_int_equal(sc.edges[e].kind, EDGE_ROD);
        assert_int_equal(sc.edges[e].colour, e < 3 ? 0 : 1);
        assert_int_equal(sc.edges[5 + e].a, e); /* the springs keep their order */
        assert_int_equal(sc.edges[5 + e].kind, EDGE_SPRING);
    }
    /* back to serial: the scene's order */
    assert_int_equal(scene_set_order(&sc, ORDER_SERIAL, err), 1);
    for (int e = 0; e < 10; e++) assert_int_equal(sc.edges[e].src, e);
    scene_free(&sc);
    /* a triangle and a tail: three colours; no two edges of a colour share a node */
    assert_true(scene_load(&sc, write_scene(TIME "[graph]\nnode = 0 0\nnode = 1 0\nnode = 0 1\nnode = 2 2\n"
                                            "edge = 0 1 rod\nedge = 1 2 spring\nedge = 1 2 rod\nedge = 2 0 strut\nedge = 2 3 rod\n"
                                            "[constraints]\norder = redblack\n[springs]\nks = 1\n"), err));
    assert_int_equal(sc.n_colours, 3);
    static const int src[5] = {0, 4, 2, 3, 1}; /* colours 0 (0-1, 2-3), 1 (1-2), 2 (2-0); then the spring */
    for (int e = 0; e < 5; e++) assert_int_equal(sc.edges[e].src, src[e]);
    for (int e = 0; e < 4; e++)
        for (int f = e + 1; f < 4; f++)
            if (sc.edges[e].colour == sc.edges[f].colour)
                assert_false(sc.edges[e].a == sc.edges[f].a || sc.edges[e].a == sc.edges[f].b || sc.edges[e].b == sc.edges[f].a ||
                             sc.edges[e].b == sc.edges[f].b);
    scene_free(&sc);
}

static void test_shipped_scenes_load(void **state)
{
    static const char *const names[] = {"ref000_rope", "hanging_rope", "pendulum", "ref001_video1", "ref001_video2", "ref001_video3", "ref001_video4",
                                        "ref002_euler", "ref002_verlet", "ref002_verlet_springs", "ref004_chain"};
    (void)state;
    for (size_t i = 0; i < sizeof names / sizeof *names; i++) {
        char path[512], err[SCENE_ERR_LEN];
        scene sc;
        snprintf(path, sizeof path, "%s/sim/scenes/%s.scene", STRAND_ROOT, names[i]);
        if (!scene_load(&sc, path, err)) fail_msg("%s", err);
        if (strstr(names[i], "video")) {
            assert_int_equal(sc.n_nodes, 12);
            assert_int_equal(sc.n_edges, 30);
            assert_int_equal(sc.dim, 3);
        }
        scene_free(&sc);
    }
}

/* scene_edit: a key's line replaced with its comment, one added at the end of its section, a
   new section; a refused value writes nothing and says which assignment or line is wrong */
static char *slurp(const char *path)
{
    static char buf[4096];
    FILE *f = fopen(path, "r");
    assert_non_null(f);
    size_t n = fread(buf, 1, sizeof buf - 1, f);
    buf[n] = 0;
    fclose(f);
    return buf;
}

static void test_scene_edit(void **state)
{
    (void)state;
    char err[SCENE_ERR_LEN], in[64], out[80];
    const char *path = write_scene("; a chain\n" TIME "frames = 10   ; ten\n\n" CHAIN "\n; the end\n");
    snprintf(in, sizeof in, "%s", path);
    snprintf(out, sizeof out, "%s.out", in);
    const char *set[] = {"time.frames=20", "chain.pinned=0", "gravity.accel=0 -981"};
    assert_true(scene_edit(in, out, 3, set, err));
    assert_string_equal(slurp(out), "; a chain\n[time]\ndt = 0.01\nframes = 20\n\n[chain]\nunits = 2\nnodes_per_unit = 3\n"
                                    "start = 0 0\nstep = 1 0\npinned = 0\n\n; the end\n\n[gravity]\naccel = 0 -981\n");
    scene sc;
    assert_true(scene_load(&sc, out, err));
    assert_int_equal(sc.frames, 20);
    scene_free(&sc);
    unlink(out);

    const char *bad_value[] = {"time.frames=20", "time.substeps=0"};
    assert_false(scene_edit(in, out, 2, bad_value, err));
    assert_non_null(strstr(err, "'time.substeps=0': "));
    assert_non_null(strstr(err, "out of range"));
    assert_int_equal(access(out, F_OK), -1);
    char tmp[96];
    snprintf(tmp, sizeof tmp, "%s.tmp", out);
    assert_int_equal(access(tmp, F_OK), -1);

    const char *bad_section[] = {"magnet.speed=3"};
    assert_false(scene_edit(in, out, 1, bad_section, err));
    assert_string_equal(err, "'magnet.speed=3': unknown section [magnet]");

    const char *bad_form[] = {"frames=3"}, *bad_comment[] = {"time.frames=3 ; three"};
    assert_false(scene_edit(in, out, 1, bad_form, err));
    assert_non_null(strstr(err, "want SECTION.KEY=VALUE"));
    assert_false(scene_edit(in, out, 1, bad_comment, err));
    assert_non_null(strstr(err, "comment character"));

    /* a contradiction found on a line of the input is blamed on that line */
    const char *narrow[] = {"format.width=12", "format.frac=16"};
    assert_false(scene_edit(in, out, 2, narrow, err));
    assert_non_null(strstr(err, "'format.frac=16': "));
    assert_int_equal(access(out, F_OK), -1);
    unlink(in);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_syntax_and_keys),         cmocka_unit_test(test_required_and_contradictions),
        cmocka_unit_test(test_graph_errors),            cmocka_unit_test(test_format_errors),
        cmocka_unit_test(test_missing_file),            cmocka_unit_test(test_chain_layout_and_defaults),
        cmocka_unit_test(test_nul_byte),               cmocka_unit_test(test_accepted_forms),
        cmocka_unit_test(test_shipped_scenes_load),       cmocka_unit_test(test_scene_edit),
        cmocka_unit_test(test_constraint_order),         cmocka_unit_test(test_table_effects),
    };
    return cmocka_run_group_tests_name("scene files", tests, NULL, NULL);
}
