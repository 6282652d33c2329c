`default_nettype none
`timescale 1ns / 1ps

`include "strand_defs.vh"

/*
 * fx_mul_pipe - the exact signed product of two W-bit words, in two pipeline stages.
 *
 * Computes prod = a * b (signed, 2W bits), exactly fx_mul's `prod`, so that a pipelined
 * datapath can round it (fx_round) in a stage of its own.
 *
 * Algorithm: each operand splits at H = ceil(W/2) into a signed high part and an
 * unsigned low part, a = aH 2^H + aL; the four partial products aH bH, aH bL, aL bH,
 * aL bL (each at most 17 x 17 bits signed at W = 32: one 18 x 18 multiplier block
 * each) are registered, then summed with their weights 2^2H, 2^H, 2^H, 1 and the sum
 * registered. Splitting is what lets a 32 x 32 product run at a multiplier block's own
 * speed: one block and its routing in the first stage, the adders in the second.
 *
 * Latency: operands on the inputs in cycle 0 give prod in cycle 2. Throughput one
 * product per clock. No reset.
 */
module fx_mul_pipe #(
    parameter integer W = 32  // operand width in bits, 8..32
) (
    input  wire           clk,
    input  wire [W-1:0]   a,     // signed
    input  wire [W-1:0]   b,     // signed
    output reg  [2*W-1:0] prod   // signed, exact
);

    `STRAND_CHECK(fx_mul_pipe_W, W >= 8 && W <= 32, ("fx_mul_pipe: W must be 8..32 (W=%0d) in %m", W))

    localparam integer H  = (W + 1) / 2;  // low part bits
    localparam integer HW = W - H;        // high part bits (signed)

    wire signed [HW-1:0] a_hi = a[W-1:H];
    wire signed [HW-1:0] b_hi = b[W-1:H];
    wire signed [H:0]    a_lo = {1'b0, a[H-1:0]};  // unsigned, as a non-negative signed value
    wire signed [H:0]    b_lo = {1'b0, b[H-1:0]};

    // stage 1: the partial products
    reg signed [2*HW-1:0] hh;
    reg signed [HW+H:0]   hl, lh;
    reg signed [2*H+1:0]  ll;
    always @(posedge clk) begin
        hh <= a_hi * b_hi;
        hl <= a_hi * b_lo;
        lh <= a_lo * b_hi;
        ll <= a_lo * b_lo;
    end

    // stage 2: their weighted sum (every term sign-extended to 2W bits)
    wire signed [2*W-1:0] hh_w = {{(2*W-2*HW){hh[2*HW-1]}}, hh};
    wire signed [2*W-1:0] hl_w = {{(2*W-HW-H-1){hl[HW+H]}}, hl};
    wire signed [2*W-1:0] lh_w = {{(2*W-HW-H-1){lh[HW+H]}}, lh};
    wire signed [2*W-1:0] ll_w = {{(2*W-2*H-2){ll[2*H+1]}}, ll};
    always @(posedge clk) prod <= (hh_w <<< (2 * H)) + ((hl_w + lh_w) <<< H) + ll_w;

endmodule

`resetall
