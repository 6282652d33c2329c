`default_nettype none
`timescale 1ns / 1ps

/*
 * tb_fx_sqrt_pipe - self-checking testbench for rtl/fx_sqrt_pipe.v: values and latency.
 *
 * Reads the vectors of fx_sqrt (tb/gen_vectors.c, unit sqrt; record: flags {0,0,0,sat},
 * radicand, y) and streams them back to back, a new radicand every clock; the result of
 * the radicand driven in cycle c must be there in cycle c + L (model/timing.c, +latency=), whatever
 * came before and after it. Plusargs: +vectors=FILE +n=COUNT
 * +latency=L (tb/unit_latency.c: model/timing.c) +name=NAME.
 * Prints one line, "PASS NAME (N vectors)" or "FAIL NAME: ...", and ends with $fatal
 * (exit status 1) on failure.
 */
module tb_fx_sqrt_pipe;

    parameter integer W         = 32;      // width under test
    parameter integer SQRT_BITS = W - 1;   // root bits resolved under test
    parameter integer STEPS     = 1;       // iterations a stage under test
    parameter integer MAXN      = 1 << 18; // capacity of the vector memory

    localparam integer FD  = 4 * ((W + 3) / 4);     // a W-bit field padded to hex digits
    localparam integer RD  = 4 * ((2 * W + 3) / 4); // the 2W-bit radicand field
    localparam integer RW  = 4 + RD + FD;           // record width
    integer            LAT;  // cycles from the operands driven to the result: +latency=, from model/timing.c

    reg [RW-1:0]    mem [0:MAXN-1];
    reg [8*64-1:0]  name;
    reg [8*256-1:0] file;
    reg [8*96-1:0]  note;  // the PASS line's figures
    integer         n, c, v;

    reg             clk = 1'b0;
    reg [2*W-1:0]   radicand = {2*W{1'b0}};
    wire [W-1:0]    result;
    wire            sat;

    fx_sqrt_pipe #(.W(W), .SQRT_BITS(SQRT_BITS), .STEPS(STEPS)) dut (.clk(clk), .radicand(radicand), .result(result), .sat(sat));

    always #5 clk = !clk;

`include "bench_vectors.vh"

    initial begin
        load_vectors("tb_fx_sqrt_pipe");
        load_latency(LAT, 1, 64);
        // cycle c: drive vector c (sampled at the edge ending cycle c), check vector c - LAT
        for (c = 0; c < n + LAT; c = c + 1) begin
            @(negedge clk);
            v = c - LAT;
            if (v >= 0 && (result !== mem[v][0 +: W] || sat !== mem[v][RW-4])) begin
                $display("FAIL %0s: vector %0d radicand %h: result %h sat %b, expected %h %b", name, v,
                         mem[v][FD +: 2*W], result, sat, mem[v][0 +: W], mem[v][RW-4]);
                $fatal(1);
            end
            radicand = c < n ? mem[c][FD +: 2*W] : {2*W{1'b0}};
        end
        $sformat(note, ", one a clock, latency %0d", LAT);
        finish_bench(0, "", note);
    end
endmodule

`resetall
