`default_nettype none
`timescale 1ns / 1ps

/*
 * tb_spring_force - self-checking testbench for rtl/spring_force.v: values and timing.
 *
 * Reads vectors written by tb/gen_vectors.c (unit "spring", DIM 2 or 3; record: flags
 * {0,0,0,valid}, a_x, a_y, a_z, a_px, a_py, a_pz, b_x, b_y, b_z, b_px, b_py, b_pz,
 * rest_len, ks, kd, f_x, f_y, f_z; z is 0 in 2D). The expected force is the one the frame engine's spring_edge()
 * (model/engine_body.h, through sim_fx_spring_edge) adds to end a's acc; valid = 0
 * where the engine adds no force (coincident ends, length 0). f is checked
 * when valid = 1 only (the callers write nothing otherwise).
 * Plusargs: +vectors=FILE +n=COUNT +name=NAME.
 *
 * The latency contract (start, busy, done) is tb/serial_latency_check.v's, instantiated here
 * with L = LATENCY. For every vector the bench checks the values, counting the
 * cycle in which start is high as cycle 0 and sampling the outputs between edges
 * (inputs are driven on the falling edge):
 *   - cycles 1 .. LATENCY-1: f, valid still hold the
 *     previous operation's values; lane k may already change from cycle
 *     LATENCY - DIM + 1 + k (spring_force.v writes the lanes one a cycle, the last in
 *     the done cycle; callers read them at done);
 *   - cycle LATENCY (model/timing.c hw_spring_latency, +latency=), the done cycle: the new
 *     f, valid;
 *   - the next operation starts back to back in the done cycle, except after every
 *     4th vector (one idle cycle) and every 16th (three): the outputs hold.
 * While busy, the inputs change to random values (in cycles 1, LATENCY/2 and
 * LATENCY-1), and every 3rd operation holds start high throughout: all must be
 * ignored (the inputs are sampled with start only). After reset, and after a reset
 * in the middle of an operation, f, valid must be 0.
 * Prints one line, "PASS NAME (N vectors)" or "FAIL NAME: ...", and ends with
 * $fatal (exit status 1) on failure or timeout.
 */
module tb_spring_force;

    parameter integer W         = 32;      // width under test
    parameter integer F         = 16;      // fraction bits under test
    parameter integer SQRT_BITS = W - 1;   // root bits resolved under test
    parameter integer DIV_BITS  = W - 1;   // quotient bits resolved under test
    parameter integer MANTISSA  = 0;       // 0: the full-width datapath; else the normalised one
    parameter integer DIM       = 2;       // 2, or 3: the z lane
    parameter integer MAXN      = 1 << 14; // capacity of the vector memory

    integer          LATENCY;  // start to done: +latency=, from model/timing.c (tb/gen_vectors.c writes it)
    localparam integer FD = 4 * ((W + 3) / 4);                  // a W-bit field padded to hex digits
    localparam integer RW = 4 + 18 * FD;                        // record width
    localparam integer NI = 15;                                 // inputs in a record

    reg [RW-1:0]     mem [0:MAXN-1];
    reg [8*64-1:0]   name;
    reg [8*256-1:0]  file;
    reg [8*600-1:0]  fail_msg;
    reg [8*480-1:0]  first_msg;
    integer          n, i, k, j, errors;
    integer          cycles, limit;
    /* verilator lint_off UNUSEDSIGNAL */
    reg [31:0]       rnd;  // one $random; at W < 32 its top bits are not used
    /* verilator lint_on UNUSEDSIGNAL */

    reg              clk = 1'b0;
    reg              reset = 1'b1;
    reg              start = 1'b0;
    // inputs in record order: a_x, a_y, a_z, a_px, a_py, a_pz, b_x, b_y, b_z, b_px, b_py, b_pz, rest_len, ks, kd
    reg  [W-1:0]     in [0:NI-1];
    wire             busy, done, valid;
    wire [W-1:0]     f_x, f_y, f_z;

    // the vector under test and the outputs expected to hold
    reg  [W-1:0]     in_i [0:NI-1];
    reg  [W-1:0]     fx_exp, fy_exp, fz_exp, prev_fx, prev_fy, prev_fz;
    reg              valid_exp, prev_valid;

    // the datapath: lanes x, y (and z when DIM = 3; in 2D the z inputs are unused and f_z is 0)
    /* verilator lint_off UNUSEDSIGNAL */
    wire [3*W-1:0]   a3 = {in[2], in[1], in[0]}, ap3 = {in[5], in[4], in[3]};
    wire [3*W-1:0]   b3 = {in[8], in[7], in[6]}, bp3 = {in[11], in[10], in[9]};
    /* verilator lint_on UNUSEDSIGNAL */
    wire [DIM*W-1:0] f_bus;
    assign f_x = f_bus[0 +: W];
    assign f_y = f_bus[W +: W];
    generate
        if (DIM == 3) begin : g_z
            assign f_z = f_bus[(DIM-1)*W +: W];
        end else begin : g_no_z
            assign f_z = {W{1'b0}};
        end
    endgenerate
    spring_force #(.W(W), .F(F), .SQRT_BITS(SQRT_BITS), .DIV_BITS(DIV_BITS), .MANTISSA(MANTISSA), .DIM(DIM)) dut (
        .clk(clk), .reset(reset), .start(start),
        .pos_a(a3[DIM*W-1:0]), .prev_a(ap3[DIM*W-1:0]), .pos_b(b3[DIM*W-1:0]), .prev_b(bp3[DIM*W-1:0]),
        .rest_len(in[12]), .ks(in[13]), .kd(in[14]),
        .busy(busy), .done(done), .f(f_bus), .valid(valid));

    initial forever #5 clk = !clk;

    // the latency contract (start, busy, done), tb/serial_latency_check.v's
    wire [31:0] contract_violations;
    serial_latency_check #(.DEPTH(256)) contract (.clk(clk), .reset(reset), .latency(LATENCY[15:0]), .start(start),
                                                  .busy(busy), .done(done), .violations(contract_violations));

    // Watchdog in clock cycles: every operation needs LATENCY+4 at most.
    initial cycles = 0;
    always @(posedge clk) begin
        cycles <= cycles + 1;
        if (cycles > limit) begin
            $display("FAIL %0s: timeout after %0d cycles", name, cycles);
            $fatal(1, "timeout");
        end
    end

    task check;
        input         cond;
        input integer cycle_no;
        begin
            if (!cond) begin
                if (errors == 0)
                    $sformat(first_msg, "vector #%0d a=(%h,%h,%h) a-=(%h,%h,%h) b=(%h,%h,%h) b-=(%h,%h,%h) rest=%h ks=%h kd=%h in cycle %0d: busy=%b done=%b f=(%h,%h,%h) valid=%b, expected f=(%h,%h,%h) valid=%b (f checked when valid)",
                             i, in_i[0], in_i[1], in_i[2], in_i[3], in_i[4], in_i[5], in_i[6], in_i[7],
                             in_i[8], in_i[9], in_i[10], in_i[11], in_i[12], in_i[13], in_i[14], cycle_no, busy, done,
                             f_x, f_y, f_z, valid, fx_exp, fy_exp, fz_exp, valid_exp);
                errors = errors + 1;
            end
        end
    endtask

    // The outputs hold the last result, idle or busy; in cycle k of an operation lane j
    // may already be new from cycle LATENCY - DIM + 1 + j on.
    wire held = f_x === prev_fx && f_y === prev_fy && f_z === prev_fz && valid === prev_valid;
    function held_in;
        input integer c;
        begin
            held_in = valid === prev_valid && (f_x === prev_fx || c >= LATENCY - DIM + 1) &&
                      (f_y === prev_fy || c >= LATENCY - DIM + 2) && (f_z === prev_fz || c >= LATENCY - DIM + 3);
        end
    endfunction

    // Inputs while busy or idle: random values; start high every 3rd operation
    // while busy (ignored), low when idle.
    task drive_other;
        input with_start;
        begin
            start = with_start && (i % 3 == 1);
            for (j = 0; j < NI; j = j + 1) begin
                rnd = $random;
                in[j] = rnd[W-1:0];
            end
        end
    endtask

    // The vector's inputs, with start.
    task drive_vector;
        begin
            start = 1'b1;
            for (j = 0; j < NI; j = j + 1) in[j] = in_i[j];
        end
    endtask

    // Reset is expected to clear the outputs.
    task check_reset;
        input integer cycle_no;
        begin
            check(f_x === {W{1'b0}} && f_y === {W{1'b0}} && f_z === {W{1'b0}} &&
                  valid === 1'b0, cycle_no);
            prev_fx = {W{1'b0}};
            prev_fy = {W{1'b0}};
            prev_fz = {W{1'b0}};
            prev_valid = 1'b0;
        end
    endtask

`include "bench_vectors.vh"

    initial begin
        limit = 1000;
        load_vectors("tb_spring_force");
        load_latency(LATENCY, 4, 256);
        limit = n * (LATENCY + 4) + 1000;
        errors = 0;
        i = -1;
        for (j = 0; j < NI; j = j + 1) begin
            in[j] = {W{1'b0}};
            in_i[j] = {W{1'b0}};
        end
        fx_exp = 0; fy_exp = 0; fz_exp = 0; valid_exp = 0;

        // Reset.
        repeat (2) @(posedge clk);
        @(negedge clk);
        reset = 1'b0;
        check_reset(-1);

        for (i = 0; i < n; i = i + 1) begin
            valid_exp = mem[i][RW-4];
            for (j = 0; j < NI; j = j + 1) in_i[j] = mem[i][(17 - j)*FD +: W];
            fx_exp    = mem[i][2*FD +: W];
            fy_exp    = mem[i][1*FD +: W];
            fz_exp    = mem[i][0*FD +: W];

            // Once, half way: a reset in the middle of an operation.
            if (i == n / 2) begin
                drive_vector;
                @(posedge clk); @(negedge clk);
                start = 1'b0;
                repeat (LATENCY / 2) @(posedge clk);
                @(negedge clk);
                reset = 1'b1;
                @(posedge clk); @(negedge clk);
                reset = 1'b0;
                check_reset(-2);
                @(posedge clk); @(negedge clk);
                check_reset(-2);
            end

            // Cycle 0: start high (the done cycle of the previous operation,
            // or after idle cycles).
            drive_vector;
            @(posedge clk); @(negedge clk);
            // Cycles 1 .. LATENCY-1: busy; the outputs hold, but for the lanes written
            // before done (lane j from cycle LATENCY - DIM + 1 + j).
            for (k = 1; k < LATENCY; k = k + 1) begin
                if (k == 1 || k == LATENCY / 2 || k == LATENCY - 1) drive_other(1'b1);
                check(held_in(k), k);
                @(posedge clk); @(negedge clk);
            end
            // Cycle LATENCY: the result, done.
            start = 1'b0;
            check(valid === valid_exp && (valid_exp === 1'b0 ||
                  (f_x === fx_exp && f_y === fy_exp && f_z === fz_exp)) && ^{f_x, f_y, f_z} !== 1'bx, LATENCY);
            prev_fx = f_x;
            prev_fy = f_y;
            prev_fz = f_z;
            prev_valid = valid;
            // Every 4th vector: idle cycles; done must have dropped, the outputs hold.
            if (i % 4 == 3) begin
                for (k = 0; k < (i % 16 == 15 ? 3 : 1); k = k + 1) begin
                    drive_other(1'b0);
                    @(posedge clk); @(negedge clk);
                    check(held, LATENCY + 1 + k);
                end
            end
        end
        @(posedge clk); @(negedge clk);  // the last cycle's contract check
        $sformat(fail_msg, "%0d value checks and %0d cycles of the latency contract failed; first value check: %0s",
                 errors, contract_violations, errors != 0 ? first_msg : "none");
        finish_bench(errors + contract_violations, fail_msg, "");
    end

endmodule

`resetall
