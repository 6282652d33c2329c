`default_nettype none
`timescale 1ns / 1ps

/*
 * exh_units - LANES copies of every arithmetic unit side by side, for the
 * Verilator exhaustive test (tb/exhaustive_units.cpp). Not synthesized.
 *
 * Lane j of a packed bus is bits [j*W +: W]. The combinational units share the
 * operand a and take their own b; the iterative units share start and take their
 * own operands, so one eval() of the model checks LANES operand pairs.
 * Each kind of unit has a clock of its own, so that the test only pays for the
 * kind it is exercising: Verilator re-evaluates logic fed by top-level inputs on
 * every eval(), so the operands of the combinational units are registered on
 * clk_comb (their outputs follow one clk_comb edge after a and b are set).
 */
module exh_units #(
    parameter integer W     = 12,    // total width in bits
    parameter integer F     = 6,     // fraction bits
    parameter integer LANES = 16     // unit copies per kind
) (
    input  wire                   clk_comb, // loads a and b into the combinational units
    input  wire                   clk_sqrt, // clock of the square roots
    input  wire                   clk_div,  // clock of the dividers
    input  wire                   reset,
    // Combinational units: a is shared, b per lane.
    input  wire [W-1:0]           a,
    input  wire [LANES*W-1:0]     b,
    output wire [LANES*W-1:0]     add_y,
    output wire [LANES-1:0]       add_sat,
    output wire [LANES*W-1:0]     sub_y,
    output wire [LANES-1:0]       sub_sat,
    output wire [LANES*W-1:0]     mul_y,
    output wire [LANES-1:0]       mul_sat,
    output wire [LANES*2*W-1:0]   mul_prod,
    output wire [LANES*W-1:0]     avg_y,
    // Iterative units: start is shared, operands per lane.
    input  wire                   start,
    input  wire [LANES*2*W-1:0]   radicand,
    output wire [LANES-1:0]       sqrt_busy,
    output wire [LANES-1:0]       sqrt_done,
    output wire [LANES*W-1:0]     sqrt_y,
    output wire [LANES-1:0]       sqrt_sat,
    input  wire [W-1:0]           num,
    input  wire [LANES*W-1:0]     den,
    output wire [LANES-1:0]       div_busy,
    output wire [LANES-1:0]       div_done,
    output wire [LANES*W-1:0]     div_y,
    output wire [LANES-1:0]       div_dbz,
    output wire [LANES-1:0]       div_sat
);

    reg [W-1:0]       a_q;
    reg [LANES*W-1:0] b_q;
    always @(posedge clk_comb) begin
        a_q <= a;
        b_q <= b;
    end

    genvar j;
    generate
        for (j = 0; j < LANES; j = j + 1) begin : lane
            fx_add #(.W(W)) u_add (
                .sub(1'b0), .a(a_q), .b(b_q[j*W +: W]), .y(add_y[j*W +: W]), .sat(add_sat[j]));
            fx_add #(.W(W)) u_sub (
                .sub(1'b1), .a(a_q), .b(b_q[j*W +: W]), .y(sub_y[j*W +: W]), .sat(sub_sat[j]));
            fx_mul #(.W(W), .F(F)) u_mul (
                .a(a_q), .b(b_q[j*W +: W]), .y(mul_y[j*W +: W]), .sat(mul_sat[j]),
                .prod(mul_prod[j*2*W +: 2*W]));
            fx_avg #(.W(W)) u_avg (
                .a(a_q), .b(b_q[j*W +: W]), .y(avg_y[j*W +: W]));
            fx_sqrt #(.W(W), .SQRT_BITS(W - 1)) u_sqrt (
                .clk(clk_sqrt), .reset(reset), .start(start), .radicand(radicand[j*2*W +: 2*W]),
                .busy(sqrt_busy[j]), .done(sqrt_done[j]), .result(sqrt_y[j*W +: W]),
                .sat(sqrt_sat[j]));
            fx_div #(.W(W), .F(F), .DIV_BITS(W - 1)) u_div (
                .clk(clk_div), .reset(reset), .start(start), .num(num), .den(den[j*W +: W]),
                .busy(div_busy[j]), .done(div_done[j]), .result(div_y[j*W +: W]),
                .div_by_zero(div_dbz[j]), .sat(div_sat[j]));
        end
    endgenerate

endmodule

`resetall
