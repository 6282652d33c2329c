`default_nettype none
`timescale 1ns / 1ps

/*
 * tb_spring_force - self-checking testbench for rtl/spring_force.v: values and timing.
 *
 * Reads vectors written by tb/gen_vectors.c (unit "spring"; record: flags
 * {0,0,0,valid}, a_x, a_y, a_px, a_py, b_x, b_y, b_px, b_py, rest_len, ks, kd, f_x,
 * f_y). The expected force is the one the frame engine's spring_edge()
 * (model/engine_body.h, through sim_fx_spring_edge) adds to end a's acc; valid = 0
 * where the engine adds no force (coincident ends, length 0). f_x, f_y are checked
 * when valid = 1 only (the callers write nothing otherwise).
 * Plusargs: +vectors=FILE +n=COUNT +name=NAME.
 *
 * For every vector it checks the latency contract of spring_force.v, counting the
 * cycle in which start is high as cycle 0 and sampling the outputs between edges
 * (inputs are driven on the falling edge):
 *   - cycles 1 .. LATENCY-1: busy = 1, done = 0, and f_x, f_y, valid still hold the
 *     previous operation's values; f_x alone may already change in cycle LATENCY-1
 *     (spring_force.v writes it one cycle before f_y; callers read them at done);
 *   - cycle LATENCY (model/timing.c hw_spring_latency, +latency=): done = 1, busy = 0, and the new
 *     f_x, f_y, valid;
 *   - the next operation starts back to back in the done cycle, except after every
 *     4th vector (one idle cycle) and every 16th (three): done must have dropped,
 *     busy stay low and the outputs hold.
 * While busy, the inputs change to random values (in cycles 1, LATENCY/2 and
 * LATENCY-1), and every 3rd operation holds start high throughout: all must be
 * ignored (the inputs are sampled with start only). After reset, and after a reset
 * in the middle of an operation, busy, done, f_x, f_y, valid must be 0.
 * Prints one line, "PASS NAME (N vectors)" or "FAIL NAME: ...", and ends with
 * $fatal (exit status 1) on failure or timeout.
 */
module tb_spring_force;

    parameter integer W         = 32;      // width under test
    parameter integer F         = 16;      // fraction bits under test
    parameter integer SQRT_BITS = W - 1;   // root bits resolved under test
    parameter integer DIV_BITS  = W - 1;   // quotient bits resolved under test
    parameter integer MAXN      = 1 << 14; // capacity of the vector memory

    integer          LATENCY;  // start to done: +latency=, from model/timing.c (tb/gen_vectors.c writes it)
    localparam integer FD = 4 * ((W + 3) / 4);                  // a W-bit field padded to hex digits
    localparam integer RW = 4 + 13 * FD;                        // record width

    reg [RW-1:0]     mem [0:MAXN-1];
    reg [8*64-1:0]   name;
    reg [8*256-1:0]  file;
    reg [8*480-1:0]  first_msg;
    integer          n, i, k, j, errors;
    integer          cycles, limit;
    /* verilator lint_off UNUSEDSIGNAL */
    reg [31:0]       rnd;  // one $random; at W < 32 its top bits are not used
    /* verilator lint_on UNUSEDSIGNAL */

    reg              clk = 1'b0;
    reg              reset = 1'b1;
    reg              start = 1'b0;
    // inputs in record order: a_x, a_y, a_px, a_py, b_x, b_y, b_px, b_py, rest_len, ks, kd
    reg  [W-1:0]     in [0:10];
    wire             busy, done, valid;
    wire [W-1:0]     f_x, f_y;

    // the vector under test and the outputs expected to hold
    reg  [W-1:0]     in_i [0:10];
    reg  [W-1:0]     fx_exp, fy_exp, prev_fx, prev_fy;
    reg              valid_exp, prev_valid;

    // the 2D datapath (DIM = 2): lanes x, y
    spring_force #(.W(W), .F(F), .SQRT_BITS(SQRT_BITS), .DIV_BITS(DIV_BITS), .DIM(2)) dut (
        .clk(clk), .reset(reset), .start(start),
        .a({in[1], in[0]}), .a_p({in[3], in[2]}), .b({in[5], in[4]}), .b_p({in[7], in[6]}),
        .rest_len(in[8]), .ks(in[9]), .kd(in[10]),
        .busy(busy), .done(done), .f({f_y, f_x}), .valid(valid));

    initial forever #5 clk = !clk;

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
                    $sformat(first_msg, "vector #%0d a=(%h,%h) a-=(%h,%h) b=(%h,%h) b-=(%h,%h) rest=%h ks=%h kd=%h in cycle %0d: busy=%b done=%b f=(%h,%h) valid=%b, expected f=(%h,%h) valid=%b (f checked when valid)",
                             i, in_i[0], in_i[1], in_i[2], in_i[3], in_i[4], in_i[5], in_i[6], in_i[7],
                             in_i[8], in_i[9], in_i[10], cycle_no, busy, done, f_x, f_y, valid,
                             fx_exp, fy_exp, valid_exp);
                errors = errors + 1;
            end
        end
    endtask

    // The outputs hold the last result, idle or busy.
    wire held_but_f_x = f_y === prev_fy && valid === prev_valid;
    wire held = held_but_f_x && f_x === prev_fx;

    // Inputs while busy or idle: random values; start high every 3rd operation
    // while busy (ignored), low when idle.
    task drive_other;
        input with_start;
        begin
            start = with_start && (i % 3 == 1);
            for (j = 0; j < 11; j = j + 1) begin
                rnd = $random;
                in[j] = rnd[W-1:0];
            end
        end
    endtask

    // The vector's inputs, with start.
    task drive_vector;
        begin
            start = 1'b1;
            for (j = 0; j < 11; j = j + 1) in[j] = in_i[j];
        end
    endtask

    // Reset is expected to clear the outputs.
    task check_reset;
        input integer cycle_no;
        begin
            check(busy === 1'b0 && done === 1'b0 && f_x === {W{1'b0}} && f_y === {W{1'b0}} && valid === 1'b0, cycle_no);
            prev_fx = {W{1'b0}};
            prev_fy = {W{1'b0}};
            prev_valid = 1'b0;
        end
    endtask

    initial begin
        limit = 1000;
        if (!$value$plusargs("name=%s", name)) name = "tb_spring_force";
        if (!$value$plusargs("vectors=%s", file) || !$value$plusargs("n=%d", n) || n < 1 || n > MAXN ||
            !$value$plusargs("latency=%d", LATENCY) || LATENCY < 4) begin
            $display("FAIL %0s: need +vectors=FILE and +n=1..%0d", name, MAXN);
            $fatal(1, "bad arguments");
        end
        limit = n * (LATENCY + 4) + 1000;
        $readmemh(file, mem, 0, n - 1);
        if (^mem[n - 1] === 1'bx) begin
            $display("FAIL %0s: vector file %0s has fewer than %0d records", name, file, n);
            $fatal(1, "short vector file");
        end
        errors = 0;
        i = -1;
        for (j = 0; j < 11; j = j + 1) begin
            in[j] = {W{1'b0}};
            in_i[j] = {W{1'b0}};
        end
        fx_exp = 0; fy_exp = 0; valid_exp = 0;

        // Reset.
        repeat (2) @(posedge clk);
        @(negedge clk);
        reset = 1'b0;
        check_reset(-1);

        for (i = 0; i < n; i = i + 1) begin
            valid_exp = mem[i][RW-4];
            for (j = 0; j < 11; j = j + 1) in_i[j] = mem[i][(12 - j)*FD +: W];
            fx_exp    = mem[i][1*FD +: W];
            fy_exp    = mem[i][0*FD +: W];

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
            // Cycles 1 .. LATENCY-1: busy; the outputs hold, but for f_x in cycle
            // LATENCY-1 (spring_force.v writes f_x in the cycle before done).
            for (k = 1; k < LATENCY; k = k + 1) begin
                if (k == 1 || k == LATENCY / 2 || k == LATENCY - 1) drive_other(1'b1);
                check(busy === 1'b1 && done === 1'b0 && (held || (k == LATENCY - 1 && held_but_f_x)), k);
                @(posedge clk); @(negedge clk);
            end
            // Cycle LATENCY: the result, done.
            start = 1'b0;
            check(busy === 1'b0 && done === 1'b1 && valid === valid_exp && (valid_exp === 1'b0 ||
                  (f_x === fx_exp && f_y === fy_exp)) && ^{f_x, f_y} !== 1'bx, LATENCY);
            prev_fx = f_x;
            prev_fy = f_y;
            prev_valid = valid;
            // Every 4th vector: idle cycles; done must have dropped, the outputs hold.
            if (i % 4 == 3) begin
                for (k = 0; k < (i % 16 == 15 ? 3 : 1); k = k + 1) begin
                    drive_other(1'b0);
                    @(posedge clk); @(negedge clk);
                    check(busy === 1'b0 && done === 1'b0 && held, LATENCY + 1 + k);
                end
            end
        end
        if (errors != 0) begin
            $display("FAIL %0s: %0d checks failed; first: %0s", name, errors, first_msg);
            $fatal(1, "mismatch");
        end
        $display("PASS %0s (%0d vectors)", name, n);
        $finish;
    end

endmodule

`resetall
