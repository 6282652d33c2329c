`default_nettype none
`timescale 1ns / 1ps

/*
 * tb_toward_pipe - self-checking testbench for rtl/toward_pipe.v: values, latency and
 * throughput.
 *
 * Reads the vectors of toward (tb/gen_vectors.c, unit toward_pipe: the frame engine's
 * own results; record: flags {0,0,excess,valid}, p_x, p_y, p_z, c_x, c_y, c_z, rest,
 * t_x, t_y, t_z; z is 0 in 2D) and streams them into the datapath (DIM 2 or 3), mostly
 * one a clock; one cycle in 5 (by a
 * fixed pseudo-random pattern) drives random operands with in_valid low. Each
 * operation carries its vector number as its tag. In every cycle the outputs are
 * checked against what went in LATENCY cycles before (+latency=, model/timing.c
 * hw_toward_pipe_latency): out_valid exactly when a vector went in, then its tag, its
 * ok (the engine's valid), its P and C (out_p, out_c: CARRY on) and, when ok, t.
 * A reset pulse in the middle of the
 * stream must clear every operation in flight (no out_valid for LATENCY cycles).
 * Plusargs: +vectors=FILE +n=COUNT +latency=L +name=NAME.
 * Prints "PASS NAME (...)" or "FAIL NAME: ..." and ends with $fatal on failure.
 */
module tb_toward_pipe;

    parameter integer W         = 32;
    parameter integer F         = 16;
    parameter integer SQRT_BITS = W - 1;
    parameter integer DIV_BITS  = W - 1;
    parameter integer MANTISSA  = 0;       // 0: the full-width datapath; else the normalised one
    parameter integer STEPS     = 1;       // the root's and divider's iterations a stage
    parameter integer DIM       = 2;
    parameter integer MAXN      = 1 << 14;

    localparam integer FD    = 4 * ((W + 3) / 4);
    localparam integer RW    = 4 + 10 * FD;
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
    reg              in_valid = 1'b0, in_excess = 1'b0;
    reg  [W-1:0]     p_x, p_y, p_z, c_x, c_y, c_z, rest;
    reg  [TAG_W-1:0] tag;
    wire             out_valid, out_ok;
    wire [TAG_W-1:0] out_tag;
    // lanes x, y (and z when DIM = 3; in 2D the z inputs are unused and the z outputs 0)
    /* verilator lint_off UNUSEDSIGNAL */
    wire [3*W-1:0]   p3 = {p_z, p_y, p_x}, c3 = {c_z, c_y, c_x};
    /* verilator lint_on UNUSEDSIGNAL */
    wire [DIM*W-1:0] t_bus, op_bus, oc_bus;  // CARRY: P and C come back beside T
    wire [3*W-1:0]   t3, op3, oc3;
    generate
        if (DIM == 3) begin : g_z
            assign t3 = t_bus;
            assign op3 = op_bus;
            assign oc3 = oc_bus;
        end else begin : g_no_z
            assign t3 = {{W{1'b0}}, t_bus};
            assign op3 = {{W{1'b0}}, op_bus};
            assign oc3 = {{W{1'b0}}, oc_bus};
        end
    endgenerate
    wire [W-1:0]     t_x = t3[0 +: W], t_y = t3[W +: W], t_z = t3[2*W +: W];

    // what went in, by cycle: valid and vector number (-1: none)
    integer          sent [0:HIST-1];

    toward_pipe #(.W(W), .F(F), .SQRT_BITS(SQRT_BITS), .DIV_BITS(DIV_BITS), .MANTISSA(MANTISSA), .STEPS(STEPS), .DIM(DIM), .TAG_W(TAG_W), .CARRY(1'b1)) dut (
        .clk(clk), .reset(reset), .in_valid(in_valid), .in_excess(in_excess),
        .in_p(p3[DIM*W-1:0]), .in_c(c3[DIM*W-1:0]), .in_rest(rest), .in_tag(tag),
        .out_valid(out_valid), .out_t(t_bus), .out_ok(out_ok), .out_tag(out_tag),
        .out_p(op_bus), .out_c(oc_bus));

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
        load_vectors("tb_toward_pipe");
        load_latency(latency, 4, HIST - 1);
        for (k = 0; k < HIST; k = k + 1) sent[k] = -1;
        next = 0;
        done_n = 0;
        resets = 0;
        rnd = 32'h1234_5678;
        // cycle cyc: check the outputs (what went in at cyc - latency), then drive cycle cyc's inputs
        for (cyc = 0; done_n < n; cyc = cyc + 1) begin
            if (cyc > 2 * n + 4 * latency + 100) fail("timeout: results missing");
            @(negedge clk);
            v = cyc >= latency ? sent[(cyc - latency) % HIST] : -1;
            if (out_valid !== (v >= 0)) fail(v >= 0 ? "out_valid low for an operation in flight" : "out_valid high with nothing sent");
            if (v >= 0) begin
                if (out_tag !== v[TAG_W-1:0]) fail("wrong tag (operations out of order)");
                // (in 2D the records' z and the z outputs here are 0)
                if (op3 !== {mem[v][7*FD +: W], mem[v][8*FD +: W], mem[v][9*FD +: W]} ||
                    oc3 !== {mem[v][4*FD +: W], mem[v][5*FD +: W], mem[v][6*FD +: W]})
                    fail("out_p, out_c are not the operation's P and C");
                if (out_ok !== mem[v][RW-4]) begin
                    $display("FAIL %0s: vector %0d: ok=%b, expected %b", name, v, out_ok, mem[v][RW-4]);
                    $fatal(1);
                end
                if (mem[v][RW-4] && (t_x !== mem[v][2*FD +: W] || t_y !== mem[v][FD +: W] || t_z !== mem[v][0 +: W])) begin
                    $display("FAIL %0s: vector %0d excess=%b p=(%h,%h,%h) c=(%h,%h,%h) rest=%h: t=(%h,%h,%h), expected (%h,%h,%h)",
                             name, v, mem[v][RW-3], mem[v][9*FD +: W], mem[v][8*FD +: W], mem[v][7*FD +: W],
                             mem[v][6*FD +: W], mem[v][5*FD +: W], mem[v][4*FD +: W], mem[v][3*FD +: W],
                             t_x, t_y, t_z, mem[v][2*FD +: W], mem[v][FD +: W], mem[v][0 +: W]);
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
                in_valid  = 1'b1;
                in_excess = mem[next][RW-3];
                p_x = mem[next][9*FD +: W]; p_y = mem[next][8*FD +: W]; p_z = mem[next][7*FD +: W];
                c_x = mem[next][6*FD +: W]; c_y = mem[next][5*FD +: W]; c_z = mem[next][4*FD +: W];
                rest = mem[next][3*FD +: W];
                tag = next[TAG_W-1:0];
                sent[cyc % HIST] = next;
                next = next + 1;
            end else begin
                in_valid = 1'b0;
                in_excess = rnd[7];
                junk = {rnd[15:0], rnd[31:16]}; p_x = junk[W-1:0];
                junk = ~rnd;                    p_y = junk[W-1:0];
                junk = rnd ^ 32'h5a5a_a5a5;     c_x = junk[W-1:0];
                junk = rnd + 32'd99;            c_y = junk[W-1:0];
                junk = rnd ^ 32'hc3c3_3c3c;     p_z = junk[W-1:0];
                junk = rnd - 32'd7;             c_z = junk[W-1:0];
                rest = rnd[W-1:0];
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
