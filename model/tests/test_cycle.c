/*
 * test_cycle.c - the cycle model against the frame engine: driven as the harness
 * drives the RTL (reset, setup writes, one step per frame), its positions at every
 * frame end must equal the frame engine's, and its cycles per frame the formula.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include <cmocka.h>

#include "cycle.h"
#include "hwgen.h"
#include "scene.h"

static void edge(cyc_model *c, const cyc_inputs *in, cyc_outputs *out)
{
    cyc_edge(c, in);
    cyc_get_outputs(c, out);
}

/* Run `frames` frames of a scene on the cycle model, checking every frame end; order >= 0
   replaces the scene's constraint order (as `--order` does). */
static void check_scene_in(const char *path, int frames, int order)
{
    scene sc;
    char err[SCENE_ERR_LEN];
    hw_params hp;
    cyc_model c;
    sim_fx ref;
    static hw_write writes[1024];
    cyc_inputs in;
    cyc_outputs out;
    int nw;

    if (!scene_load(&sc, path, err)) fail_msg("%s", err);
    if (order >= 0 && scene_set_order(&sc, (constraint_order)order, err) < 0) fail_msg("%s", err);
    assert_null(hw_check(&sc, err, sizeof err));
    hw_params_of(&sc, &hp);
    assert_true(cyc_init(&c, &hp));
    assert_true(sim_fx_init(&ref, &sc, &sc.fmt));
    nw = hw_setup_writes(&sc, &ref, writes, 1024);
    assert_true(nw <= 1024);

    memset(&in, 0, sizeof in);
    in.reset = true;
    for (int i = 0; i < 3; i++) edge(&c, &in, &out);
    in.reset = false;
    for (int i = 0; i < nw; i++) {
        in.cfg_we = true;
        in.cfg_addr = (uint32_t)writes[i].addr;
        in.cfg_data = writes[i].data;
        edge(&c, &in, &out);
    }
    in.cfg_we = false;
    do edge(&c, &in, &out);
    while (out.phase != PH_IDLE);
    for (int i = 0; i < sc.n_nodes; i++) /* the init walk or the loads laid the nodes out as the engine does */
        for (int a = 0; a < 3; a++) assert_int_equal(cyc_node_word(&c, i, a), hw_word(&sc.fmt, ref.pos[i][a]));

    for (int f = 0; f < frames; f++) {
        double m[3];
        bool down;
        long cycles = 0;
        scene_mouse_at(&sc, f, m, &down);
        in.mouse_x = hw_word(&sc.fmt, fx_from_double(&sc.fmt, m[0]));
        in.mouse_y = hw_word(&sc.fmt, fx_from_double(&sc.fmt, m[1]));
        in.mouse_z = hw_word(&sc.fmt, fx_from_double(&sc.fmt, m[2]));
        in.mouse_down = sc.en_mouse && down;
        in.step = true;
        do {
            edge(&c, &in, &out);
            in.step = false;
            cycles++;
        } while (!out.frame_done && cycles < 10 * hw_cycles_per_frame(&hp));
        assert_int_equal(cycles, hw_cycles_per_frame(&hp));
        sim_fx_frame(&ref);
        for (int i = 0; i < sc.n_nodes; i++)
            for (int a = 0; a < 3; a++)
                if (cyc_node_word(&c, i, a) != hw_word(&sc.fmt, ref.pos[i][a]))
                    fail_msg("%s frame %d node %d axis %d: cycle model %08x, frame engine %08x", path, f + 1, i, a,
                             cyc_node_word(&c, i, a), hw_word(&sc.fmt, ref.pos[i][a]));
    }
    sim_fx_free(&ref);
    cyc_free(&c);
    scene_free(&sc);
}

static void check_scene(const char *path, int frames) { check_scene_in(path, frames, -1); }

static void test_ref000_rope(void **state)
{
    (void)state;
    check_scene(STRAND_ROOT "/sim/scenes/ref000_rope.scene", 240);
}

static void test_chain_q10_8(void **state)
{
    (void)state;
    check_scene(STRAND_ROOT "/tb/scenes/chain_q10_8.scene", 80);
}

static void test_chain_k4_bits(void **state)
{
    (void)state;
    check_scene(STRAND_ROOT "/tb/scenes/chain_k4_bits.scene", 60);
}

static void test_pairwise_scenes(void **state)
{
    (void)state;
    check_scene(STRAND_ROOT "/sim/scenes/pendulum.scene", 120);
    check_scene(STRAND_ROOT "/sim/scenes/hanging_rope.scene", 40);
    check_scene(STRAND_ROOT "/sim/scenes/ref002_verlet.scene", 20);
}

/* Springs on chains: the spring pass's forces, gathered before the Verlet pass. */
static void test_spring_scenes(void **state)
{
    (void)state;
    check_scene(STRAND_ROOT "/sim/scenes/ref004_chain.scene", 60);
    check_scene(STRAND_ROOT "/sim/scenes/ref002_verlet_springs.scene", 3);
    check_scene(STRAND_ROOT "/sim/scenes/hard_stiff_k10000.scene", 30);
}

/* Graph bodies, 2D and 3D: nodes and edges loaded by register writes, the edge passes. */
static void test_graph_scenes(void **state)
{
    (void)state;
    check_scene(STRAND_ROOT "/sim/scenes/spring_pair.scene", 120);
    check_scene(STRAND_ROOT "/sim/scenes/ref001_video1.scene", 30);
    check_scene(STRAND_ROOT "/sim/scenes/ref001_video2.scene", 200); /* the ground is reached */
}

/* A graph's pipelined pass (graph_stream): its rods by colour, the pipe drained between colours. */
static void test_graph_stream(void **state)
{
    (void)state;
    check_scene_in(STRAND_ROOT "/tb/scenes/graph3d_q12.scene", 60, ORDER_REDBLACK); /* three colours, a pinned end */
    check_scene_in(STRAND_ROOT "/sim/scenes/ref001_video2.scene", 200, ORDER_REDBLACK);
}

/* The grab form of the mouse: the scan at the frame start, the held node on the pointer. */
static void test_grab_scenes(void **state)
{
    (void)state;
    check_scene(STRAND_ROOT "/sim/scenes/hard_mouse_grab.scene", 300);
    check_scene(STRAND_ROOT "/tb/scenes/chain_grab_3d.scene", 60);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_graph_scenes),
        cmocka_unit_test(test_graph_stream),
        cmocka_unit_test(test_grab_scenes),
        cmocka_unit_test(test_spring_scenes),
        cmocka_unit_test(test_pairwise_scenes),
        cmocka_unit_test(test_ref000_rope),
        cmocka_unit_test(test_chain_q10_8),
        cmocka_unit_test(test_chain_k4_bits),
    };
    return cmocka_run_group_tests_name("cycle model against the frame engine", tests, NULL, NULL);
}
