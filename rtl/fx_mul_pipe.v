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
 * unsigned low part, a = aH 2^H + aL. Three products, not four (Karatsuba):
 *     hh = aH bH,   ll = aL bL,   m = (aH + aL)(bH + bL)
 * give the middle term aH bL + aL bH = m - hh - ll. At W = 32 the parts are 16 bits
 * and their sums 18 bits signed, so each product is one 18 x 18 multiplier block: a
 * product takes three blocks, not the four of the schoolbook split (aH bH, aH bL, aL bH,
 * aL bL). The three are registered, then summed as hh 2^2H + (m - hh - ll) 2^H + ll and
 * the sum registered. Splitting is what lets a 32 x 32 product run at a multiplier
 * block's own speed: the part sums and one block in the first stage, the adders in the
 * second. Every step is exact, so prod is a * b bit for bit.
 *
 * Operands of at most ONE_BLOCK_W bits (18: the ECP5's MULT18X18D, a signed 18 x 18
 * block) need no split: the first stage registers the operands and the second is one
 * block's product, registered, so the latency stays 2 and a Q10.8 datapath takes one
 * block a product, not three. The operands' registers feed the block alone, so they
 * sit beside it: the route from the caller's registers to a multiplier column gets a
 * cycle of its own (as the block's own input registers would give, which synthesis
 * does not use). ONE_BLOCK_W = 0 forces the split at any width (the unit bench
 * checks the split exhaustively at W = 8 that way).
 *
 * Latency: operands on the inputs in cycle 0 give prod in cycle 2. Throughput one
 * product per clock. No reset.
 */
module fx_mul_pipe #(
    parameter integer W           = 32,  // operand width in bits, 8..32
    parameter integer ONE_BLOCK_W = 18   // widths up to this take one multiplier, not a split
) (
    input  wire           clk,
    input  wire [W-1:0]   a,     // signed
    input  wire [W-1:0]   b,     // signed
    output reg  [2*W-1:0] prod   // signed, exact
);

    `STRAND_CHECK(fx_mul_pipe_W, W >= 8 && W <= 32, ("fx_mul_pipe: W must be 8..32 (W=%0d) in %m", W))

    generate if (W <= ONE_BLOCK_W) begin : g_one_block
        // stage 1: the operands registered; stage 2: their product in one block, registered
        reg signed [W-1:0] a_s1, b_s1;
        always @(posedge clk) begin
            a_s1 <= a;
            b_s1 <= b;
            prod <= a_s1 * b_s1;
        end
    end else begin : g_split
        localparam integer H  = (W + 1) / 2;  // low part bits
        localparam integer HW = W - H;        // high part bits (signed)

        wire signed [HW-1:0] a_hi = a[W-1:H];
        wire signed [HW-1:0] b_hi = b[W-1:H];
        wire        [H-1:0]  a_lo = a[H-1:0];  // unsigned
        wire        [H-1:0]  b_lo = b[H-1:0];
        // aH + aL lies in [-2^(HW-1), 2^(HW-1) - 1 + 2^H - 1]: H + 2 bits signed (HW <= H)
        wire signed [H+1:0]  a_sum = {{(H+2-HW){a_hi[HW-1]}}, a_hi} + {2'b00, a_lo};
        wire signed [H+1:0]  b_sum = {{(H+2-HW){b_hi[HW-1]}}, b_hi} + {2'b00, b_lo};

        // stage 1: the three products
        reg signed [2*HW-1:0]  hh;
        reg        [2*H-1:0]   ll;   // unsigned
        reg signed [2*H+3:0]   m;
        always @(posedge clk) begin
            hh <= a_hi * b_hi;
            ll <= a_lo * b_lo;
            m  <= a_sum * b_sum;
        end

        // stage 2: the middle term m - hh - ll (|aH bL + aL bH| < 2^(HW+H)) and the weighted
        // sum, every term sign-extended to 2W bits
        wire signed [2*W-1:0] hh_w  = {{(2*W-2*HW){hh[2*HW-1]}}, hh};
        wire signed [2*W-1:0] ll_w  = {{(2*W-2*H){1'b0}}, ll};
        wire signed [2*W-1:0] m_w   = {{(2*W-2*H-4){m[2*H+3]}}, m};
        wire signed [2*W-1:0] mid_w = m_w - hh_w - ll_w;
        always @(posedge clk) prod <= (hh_w <<< (2 * H)) + (mid_w <<< H) + ll_w;
    end endgenerate

endmodule

`resetall
