`default_nettype none
`timescale 1ns / 1ps

/*
 * tb_toward - self-checking testbench for rtl/toward.v: values and timing.
 *
 * Reads vectors written by tb/gen_vectors.c (unit "toward", DIM 2 or 3; record: flags
 * {0,0,excess,valid}, p_x, p_y, p_z, c_x, c_y, c_z, rest_len, t_x, t_y, t_z; z is 0
 * in 2D). The expected values
 * are the frame engine's own: excess = 0 the centred rule's target
 * (model/engine_body.h toward(), through sim_fx_centred_node), excess = 1 the
 * pairwise rule's excess (through sim_fx_pair_edge); valid = 0 where the engine
 * skips the constraint for a zero length. t is checked when valid = 1 only
 * (the callers ignore them otherwise).
 * Plusargs: +vectors=FILE +n=COUNT +name=NAME.
 *
 * The latency contract (start, busy, done) is tb/serial_latency_check.v's, instantiated here
 * with L = LATENCY. For every vector the bench checks the values, counting the cycle
 * in which start is high as cycle 0 and sampling the outputs between edges (inputs
 * are driven on the falling edge):
 *   - cycles 1 .. LATENCY-1: t, valid still hold the
 *     previous operation's values; lane k may already change from cycle
 *     LATENCY - DIM + 1 + k (toward.v writes the lanes one a cycle, the last in the
 *     done cycle; callers read them at done);
 *   - cycle LATENCY (model/timing.c hw_toward_latency, +latency=), the done cycle: the new
 *     t, valid;
 *   - the next operation starts back to back in the done cycle, except after every
 *     4th vector (one idle cycle) and every 16th (three): the outputs hold.
 * While busy, the inputs change to random values (in cycles 1, LATENCY/2 and
 * LATENCY-1), and every 3rd operation holds start high throughout: all must be
 * ignored (the inputs are sampled with start only). After reset, and after a reset
 * in the middle of an operation, t_x, t_y, valid must be 0.
 * Prints one line, "PASS NAME (N vectors)" or "FAIL NAME: ...", and ends with
 * $fatal (exit status 1) on failure or timeout.
 */
module tb_toward;

    parameter integer W         = 32;      // width under test
    parameter integer F         = 16;      // fraction bits under test
    parameter integer SQRT_BITS = W - 1;   // root bits resolved under test
    parameter integer DIV_BITS  = W - 1;   // quotient bits resolved under test
    parameter integer MANTISSA  = 0;       // 0: the full-width datapath; else the normalised one
    parameter integer DIM       = 2;       // 2, or 3: the z lane
    parameter integer MAXN      = 1 << 14; // capacity of the vector memory

    integer          LATENCY;  // start to done: +latency=, from model/timing.c (tb/gen_vectors.c writes it)
    localparam integer FD = 4 * ((W + 3) / 4);             // a W-bit field padded to hex digits
    localparam integer RW = 4 + 10 * FD;                   // record width

    reg [RW-1:0]     mem [0:MAXN-1];
    reg [8*64-1:0]   name;
    reg [8*256-1:0]  file;
    reg [8*600-1:0]  fail_msg;
    reg [8*400-1:0]  first_msg;
    integer          n, i, k, errors;
    integer          cycles, limit;
    /* verilator lint_off UNUSEDSIGNAL */
    reg [31:0]       rnd;  // one $random; at W < 32 its top bits are not used
    /* verilator lint_on UNUSEDSIGNAL */

    reg              clk = 1'b0;
    reg              reset = 1'b1;
    reg              start = 1'b0;
    reg              excess = 1'b0;
    reg  [W-1:0]     p_x = {W{1'b0}}, p_y = {W{1'b0}}, p_z = {W{1'b0}}, c_x = {W{1'b0}}, c_y = {W{1'b0}}, c_z = {W{1'b0}};
    reg  [W-1:0]     rest_len = {W{1'b0}};
    wire             busy, done, valid;
    wire [W-1:0]     t_x, t_y, t_z;

    // the vector under test and the outputs expected to hold
    reg  [W-1:0]     px_i, py_i, pz_i, cx_i, cy_i, cz_i, rest_i, tx_exp, ty_exp, tz_exp, prev_tx, prev_ty, prev_tz;
    reg              ex_i, valid_exp, prev_valid;

    // the datapath: lanes x, y (and z when DIM = 3; in 2D the z inputs are unused and t_z is 0)
    /* verilator lint_off UNUSEDSIGNAL */
    wire [3*W-1:0]   p3 = {p_z, p_y, p_x}, c3 = {c_z, c_y, c_x};
    /* verilator lint_on UNUSEDSIGNAL */
    wire [DIM*W-1:0] t_bus;
    assign t_x = t_bus[0 +: W];
    assign t_y = t_bus[W +: W];
    generate
        if (DIM == 3) begin : g_z
            assign t_z = t_bus[(DIM-1)*W +: W];
        end else begin : g_no_z
            assign t_z = {W{1'b0}};
        end
    endgenerate
    toward #(.W(W), .F(F), .SQRT_BITS(SQRT_BITS), .DIV_BITS(DIV_BITS), .MANTISSA(MANTISSA), .DIM(DIM)) dut (
        .clk(clk), .reset(reset), .start(start), .excess(excess),
        .p(p3[DIM*W-1:0]), .c(c3[DIM*W-1:0]), .rest_len(rest_len),
        .busy(busy), .done(done), .t(t_bus), .valid(valid));

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
                    $sformat(first_msg, "vector #%0d excess=%b p=(%h,%h,%h) c=(%h,%h,%h) rest=%h in cycle %0d: busy=%b done=%b t=(%h,%h,%h) valid=%b, expected t=(%h,%h,%h) valid=%b (t checked when valid)",
                             i, ex_i, px_i, py_i, pz_i, cx_i, cy_i, cz_i, rest_i, cycle_no, busy, done, t_x, t_y, t_z, valid,
                             tx_exp, ty_exp, tz_exp, valid_exp);
                errors = errors + 1;
            end
        end
    endtask

    // The outputs hold the last result, idle or busy; in cycle k of an operation lane j
    // may already be new from cycle LATENCY - DIM + 1 + j on.
    wire held = t_x === prev_tx && t_y === prev_ty && t_z === prev_tz && valid === prev_valid;
    function held_in;
        input integer c;
        begin
            held_in = valid === prev_valid && (t_x === prev_tx || c >= LATENCY - DIM + 1) &&
                      (t_y === prev_ty || c >= LATENCY - DIM + 2) && (t_z === prev_tz || c >= LATENCY - DIM + 3);
        end
    endfunction

    // Inputs while busy or idle: random values; start high every 3rd operation
    // while busy (ignored), low when idle.
    task drive_other;
        input with_start;
        begin
            start = with_start && (i % 3 == 1);
            rnd = $random; p_x = rnd[W-1:0];
            rnd = $random; p_y = rnd[W-1:0];
            rnd = $random; c_x = rnd[W-1:0];
            rnd = $random; c_y = rnd[W-1:0];
            rnd = $random; p_z = rnd[W-1:0];
            rnd = $random; c_z = rnd[W-1:0];
            rnd = $random; rest_len = rnd[W-1:0];
            excess = rnd[W-1];
        end
    endtask

    // Reset is expected to clear the outputs.
    task check_reset;
        input integer cycle_no;
        begin
            check(t_x === {W{1'b0}} && t_y === {W{1'b0}} && t_z === {W{1'b0}} &&
                  valid === 1'b0, cycle_no);
            prev_tx = {W{1'b0}};
            prev_ty = {W{1'b0}};
            prev_tz = {W{1'b0}};
            prev_valid = 1'b0;
        end
    endtask

`include "bench_vectors.vh"

    initial begin
        limit = 1000;
        load_vectors("tb_toward");
        load_latency(LATENCY, 4, 256);
        limit = n * (LATENCY + 4) + 1000;
        errors = 0;
        i = -1;
        px_i = 0; py_i = 0; pz_i = 0; cx_i = 0; cy_i = 0; cz_i = 0; rest_i = 0; ex_i = 0;
        tx_exp = 0; ty_exp = 0; tz_exp = 0; valid_exp = 0;

        // Reset.
        repeat (2) @(posedge clk);
        @(negedge clk);
        reset = 1'b0;
        check_reset(-1);

        for (i = 0; i < n; i = i + 1) begin
            ex_i      = mem[i][RW-3];
            valid_exp = mem[i][RW-4];
            px_i      = mem[i][9*FD +: W];
            py_i      = mem[i][8*FD +: W];
            pz_i      = mem[i][7*FD +: W];
            cx_i      = mem[i][6*FD +: W];
            cy_i      = mem[i][5*FD +: W];
            cz_i      = mem[i][4*FD +: W];
            rest_i    = mem[i][3*FD +: W];
            tx_exp    = mem[i][2*FD +: W];
            ty_exp    = mem[i][1*FD +: W];
            tz_exp    = mem[i][0*FD +: W];

            // Once, half way: a reset in the middle of an operation.
            if (i == n / 2) begin
                start = 1'b1;
                excess = ex_i; p_x = px_i; p_y = py_i; p_z = pz_i; c_x = cx_i; c_y = cy_i; c_z = cz_i; rest_len = rest_i;
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
            start = 1'b1;
            excess = ex_i; p_x = px_i; p_y = py_i; p_z = pz_i; c_x = cx_i; c_y = cy_i; c_z = cz_i; rest_len = rest_i;
            @(posedge clk); @(negedge clk);
            // Cycles 1 .. LATENCY-1: busy; the outputs hold, but for the lanes written
            // before done (toward.v writes lane j in cycle LATENCY - DIM + 1 + j).
            for (k = 1; k < LATENCY; k = k + 1) begin
                if (k == 1 || k == LATENCY / 2 || k == LATENCY - 1) drive_other(1'b1);
                check(held_in(k), k);
                @(posedge clk); @(negedge clk);
            end
            // Cycle LATENCY: the result, done.
            start = 1'b0;
            check(valid === valid_exp && (valid_exp === 1'b0 ||
                  (t_x === tx_exp && t_y === ty_exp && t_z === tz_exp)) && ^{t_x, t_y, t_z} !== 1'bx, LATENCY);
            prev_tx = t_x;
            prev_ty = t_y;
            prev_tz = t_z;
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
