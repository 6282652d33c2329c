`default_nettype none
`timescale 1ns / 1ps

/*
 * tb_fx_div_pipe - self-checking testbench for rtl/fx_div_pipe.v: values and latency.
 *
 * Reads the vectors of fx_div (tb/gen_vectors.c, unit div; record: flags {0,0,sat,dbz},
 * num, den, y) and streams them back to back, new operands every clock; the result of
 * the operands driven in cycle c must be there in cycle c + L (model/timing.c, +latency=), whatever
 * came before and after them. Plusargs: +vectors=FILE +n=COUNT
 * +latency=L (tb/unit_latency.c: model/timing.c) +name=NAME.
 * Prints one line, "PASS NAME (N vectors)" or "FAIL NAME: ...", and ends with $fatal
 * (exit status 1) on failure.
 */
module tb_fx_div_pipe;

    parameter integer W        = 32;      // width under test
    parameter integer F        = 16;      // fraction bits under test
    parameter integer DIV_BITS = W - 1;   // quotient bits resolved under test
    parameter integer STEPS    = 1;       // iterations a stage under test
    parameter integer MAXN     = 1 << 18; // capacity of the vector memory

    localparam integer FD  = 4 * ((W + 3) / 4); // a W-bit field padded to hex digits
    localparam integer RW  = 4 + 3 * FD;        // record width
    integer            LAT;  // cycles from the operands driven to the result: +latency=, from model/timing.c

    reg [RW-1:0]    mem [0:MAXN-1];
    reg [8*64-1:0]  name;
    reg [8*256-1:0] file;
    reg [8*96-1:0]  note;  // the PASS line's figures
    integer         n, c, v;

    reg             clk = 1'b0;
    reg [W-1:0]     num = {W{1'b0}}, den = {W{1'b0}};
    wire [W-1:0]    result;
    wire            sat, dbz;

    fx_div_pipe #(.W(W), .F(F), .DIV_BITS(DIV_BITS), .STEPS(STEPS)) dut (
        .clk(clk), .num(num), .den(den), .result(result), .div_by_zero(dbz), .sat(sat));

    always #5 clk = !clk;

`include "bench_vectors.vh"

    initial begin
        load_vectors("tb_fx_div_pipe");
        load_latency(LAT, 1, 64);
        for (c = 0; c < n + LAT; c = c + 1) begin
            @(negedge clk);
            v = c - LAT;
            if (v >= 0 && (result !== mem[v][0 +: W] || sat !== mem[v][RW-3] || dbz !== mem[v][RW-4])) begin
                $display("FAIL %0s: vector %0d %h / %h: result %h sat %b dbz %b, expected %h %b %b", name, v,
                         mem[v][2*FD +: W], mem[v][FD +: W], result, sat, dbz, mem[v][0 +: W], mem[v][RW-3],
                         mem[v][RW-4]);
                $fatal(1);
            end
            num = c < n ? mem[c][2*FD +: W] : {W{1'b0}};
            den = c < n ? mem[c][FD +: W] : {W{1'b0}};
        end
        $sformat(note, ", one a clock, latency %0d", LAT);
        finish_bench(0, "", note);
    end
endmodule

`resetall
