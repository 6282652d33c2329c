`default_nettype none
`timescale 1ns / 1ps

/*
 * tb_spring_force_pipe - self-checking testbench for rtl/spring_force_pipe.v: values,
 * latency and throughput.
 *
 * Reads the vectors of spring_force (tb/gen_vectors.c, unit spring_pipe: the frame
 * engine's own spring_edge() results; record: flags {0,0,0,valid}, a_x, a_y, a_z, a_px,
 * a_py, a_pz, b_x, b_y, b_z, b_px, b_py, b_pz, rest, ks, kd, f_x, f_y, f_z; z is 0 in 2D)
 * and streams them into the datapath (DIM 2 or 3), mostly one a clock; one cycle in 8 (by a fixed pseudo-random pattern) drives random
 * operands with in_valid low. Each operation carries its vector number as its tag. In
 * every cycle the outputs are checked against what went in LATENCY cycles before
 * (+latency=, model/timing.c hw_spring_pipe_latency): out_valid exactly when a vector
 * went in, then its tag, its ok (the engine's valid) and, when ok, f. A reset
 * pulse in the middle of the stream must clear every operation in flight.
 * Plusargs: +vectors=FILE +n=COUNT +latency=L +name=NAME.
 * Prints "PASS NAME (...)" or "FAIL NAME: ..." and ends with $fatal on failure.
 */
module tb_spring_force_pipe;

    parameter integer W         = 32;
    parameter integer F         = 16;
    parameter integer SQRT_BITS = W - 1;
    parameter integer DIV_BITS  = W - 1;
    parameter integer MANTISSA  = 0;       // 0: the full-width datapath; else the normalised one
    parameter integer STEPS     = 1;       // the root's and divider's iterations a stage
    parameter integer DIM       = 2;
    parameter integer MAXN      = 1 << 14;

    localparam integer FD    = 4 * ((W + 3) / 4);
    localparam integer RW    = 4 + 18 * FD;
    localparam integer TAG_W = 16;
    localparam integer HIST  = 256;  // cycles of history kept (LATENCY must be below)

    reg [RW-1:0]    mem [0:MAXN-1];
    reg [8*64-1:0]  name;
    reg [8*256-1:0] file;
    reg [8*96-1:0]  note;  // the PASS line's figures
    integer         n, latency, cyc, next, done_n, resets;
    reg [31:0]      rnd;
    /* verilator lint_off UNUSEDSIGNAL */
    reg [31:0]      junk;  // operands of the idle cycles (its top bits unused at W < 32)
    /* verilator lint_on UNUSEDSIGNAL */

    reg              clk = 1'b0, reset = 1'b1;
    reg              in_valid = 1'b0;
    // in record order: a_x, a_y, a_z, a_px, a_py, a_pz, b_x, b_y, b_z, b_px, b_py, b_pz, rest, ks, kd
    reg  [W-1:0]     in_i [0:14];
    reg  [TAG_W-1:0] tag;
    wire             out_valid, out_ok;
    wire [TAG_W-1:0] out_tag;
    // lanes x, y (and z when DIM = 3; in 2D the z inputs are unused and f_z is 0)
    /* verilator lint_off UNUSEDSIGNAL */
    wire [3*W-1:0]   a3 = {in_i[2], in_i[1], in_i[0]}, ap3 = {in_i[5], in_i[4], in_i[3]};
    wire [3*W-1:0]   b3 = {in_i[8], in_i[7], in_i[6]}, bp3 = {in_i[11], in_i[10], in_i[9]};
    /* verilator lint_on UNUSEDSIGNAL */
    wire [DIM*W-1:0] f_bus;
    wire [3*W-1:0]   f3;
    generate
        if (DIM == 3) begin : g_z
            assign f3 = f_bus;
        end else begin : g_no_z
            assign f3 = {{W{1'b0}}, f_bus};
        end
    endgenerate
    wire [W-1:0]     f_x = f3[0 +: W], f_y = f3[W +: W], f_z = f3[2*W +: W];

    // what went in, by cycle: the vector number (-1: none)
    integer          sent [0:HIST-1];

    spring_force_pipe #(.W(W), .F(F), .SQRT_BITS(SQRT_BITS), .DIV_BITS(DIV_BITS), .MANTISSA(MANTISSA), .STEPS(STEPS), .DIM(DIM), .TAG_W(TAG_W)) dut (
        .clk(clk), .reset(reset), .in_valid(in_valid),
        .in_a(a3[DIM*W-1:0]), .in_ap(ap3[DIM*W-1:0]), .in_b(b3[DIM*W-1:0]), .in_bp(bp3[DIM*W-1:0]),
        .in_rest(in_i[12]), .in_ks(in_i[13]), .in_kd(in_i[14]), .in_tag(tag),
        .out_valid(out_valid), .out_f(f_bus), .out_ok(out_ok), .out_tag(out_tag));

    initial forever #5 clk = !clk;

    task fail;
        input [8*200-1:0] what;
        begin
            $display("FAIL %0s: cycle %0d: %0s", name, cyc, what);
            $fatal(1);
        end
    endtask

    integer v, k;
`include "bench_vectors.vh"

    initial begin
        load_vectors("tb_spring_force_pipe");
        load_latency(latency, 4, HIST - 1);
        for (k = 0; k < HIST; k = k + 1) sent[k] = -1;
        next = 0;
        done_n = 0;
        resets = 0;
        rnd = 32'h8765_4321;
        // cycle cyc: check the outputs (what went in at cyc - latency), then drive cycle cyc's inputs
        for (cyc = 0; done_n < n; cyc = cyc + 1) begin
            if (cyc > 2 * n + 4 * latency + 100) fail("timeout: results missing");
            @(negedge clk);
            v = cyc >= latency ? sent[(cyc - latency) % HIST] : -1;
            if (out_valid !== (v >= 0)) fail(v >= 0 ? "out_valid low for an operation in flight" : "out_valid high with nothing sent");
            if (v >= 0) begin
                if (out_tag !== v[TAG_W-1:0]) fail("wrong tag (operations out of order)");
                if (out_ok !== mem[v][RW-4]) begin
                    $display("FAIL %0s: vector %0d: ok=%b, expected %b", name, v, out_ok, mem[v][RW-4]);
                    $fatal(1);
                end
                if (mem[v][RW-4] && (f_x !== mem[v][2*FD +: W] || f_y !== mem[v][FD +: W] || f_z !== mem[v][0 +: W])) begin
                    $display("FAIL %0s: vector %0d: f=(%h,%h,%h), expected (%h,%h,%h)", name, v, f_x, f_y, f_z,
                             mem[v][2*FD +: W], mem[v][FD +: W], mem[v][0 +: W]);
                    $fatal(1);
                end
                done_n = done_n + 1;
            end
            // the inputs of cycle cyc
            rnd = rnd * 32'd1103515245 + 32'd12345;
            reset = cyc < 2 || (cyc == 2 + n / 2);  // one reset pulse in the middle
            if (reset) begin
                if (cyc >= 2) resets = resets + 1;
                // what was in flight is dropped, and sent again after the reset
                for (k = 0; k < HIST; k = k + 1) sent[k] = -1;
                next = done_n;
            end
            if (!reset && next < n && rnd[20:18] != 3'd0) begin
                in_valid = 1'b1;
                for (k = 0; k < 15; k = k + 1) in_i[k] = mem[next][(17 - k)*FD +: W];
                tag = next[TAG_W-1:0];
                sent[cyc % HIST] = next;
                next = next + 1;
            end else begin
                in_valid = 1'b0;
                for (k = 0; k < 15; k = k + 1) begin
                    junk = rnd ^ (32'h9e37_79b9 * k);
                    in_i[k] = junk[W-1:0];
                end
                tag = rnd[TAG_W-1:0];
                sent[cyc % HIST] = -1;
            end
        end
        if (done_n != n) begin
            $display("FAIL %0s: %0d of %0d results came out", name, done_n, n);
            $fatal(1);
        end
        $sformat(note, ", one a clock with gaps, latency %0d, %0d reset in flight", latency, resets);
        finish_bench(0, "", note);
    end
endmodule

`resetall
