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
 * block a product, not three. ONE_BLOCK_W = 0 forces the split at any width (the unit
 * bench checks the split exhaustively at W = 8 that way).
 *
 * On the ECP5 (STRAND_ECP5_DSP, which make synth defines for its ECP5 flows only) the
 * one-block product is a MULT18X18D instantiated with its own input and output
 * registers: the same two stages, inside the block. Yosys maps a `*` to the block
 * without them, so the stage registers were flip-flops the placer could leave far
 * from the multiplier column (the q10_6x256 build once had a block 49 rows from the
 * registers on both sides, 8.2 ns of routing around its 3.9 ns). Inside the block a
 * cycle holds one route and no multiplier. Simulation uses the behavioural branch;
 * tb/ecp5_mult18x18d.v models the block for the configuration used here, and the
 * unit bench runs the ECP5 branch against it (fx_mul_pipe_w18_ecp5dsp_random).
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
`ifdef STRAND_ECP5_DSP
        // the two stages in the block: input registers (A, B) and output register (P), CLK0
        wire [17:0] a18 = {{(18-W){a[W-1]}}, a};
        wire [17:0] b18 = {{(18-W){b[W-1]}}, b};
        wire [35:0] p36;
        MULT18X18D #(
            .REG_INPUTA_CLK("CLK0"), .REG_INPUTB_CLK("CLK0"), .REG_OUTPUT_CLK("CLK0"),
            .REG_PIPELINE_CLK("NONE")
        ) u_mult (
            .A0(a18[0]), .A1(a18[1]), .A2(a18[2]), .A3(a18[3]), .A4(a18[4]), .A5(a18[5]),
            .A6(a18[6]), .A7(a18[7]), .A8(a18[8]), .A9(a18[9]), .A10(a18[10]), .A11(a18[11]),
            .A12(a18[12]), .A13(a18[13]), .A14(a18[14]), .A15(a18[15]), .A16(a18[16]), .A17(a18[17]),
            .B0(b18[0]), .B1(b18[1]), .B2(b18[2]), .B3(b18[3]), .B4(b18[4]), .B5(b18[5]),
            .B6(b18[6]), .B7(b18[7]), .B8(b18[8]), .B9(b18[9]), .B10(b18[10]), .B11(b18[11]),
            .B12(b18[12]), .B13(b18[13]), .B14(b18[14]), .B15(b18[15]), .B16(b18[16]), .B17(b18[17]),
            .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0),
            .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
            .SIGNEDA(1'b1), .SIGNEDB(1'b1), .SOURCEA(1'b0), .SOURCEB(1'b0),
            .CLK0(clk), .CLK1(1'b0), .CLK2(1'b0), .CLK3(1'b0),
            .CE0(1'b1), .CE1(1'b0), .CE2(1'b0), .CE3(1'b0),
            .RST0(1'b0), .RST1(1'b0), .RST2(1'b0), .RST3(1'b0),
            .P0(p36[0]), .P1(p36[1]), .P2(p36[2]), .P3(p36[3]), .P4(p36[4]), .P5(p36[5]),
            .P6(p36[6]), .P7(p36[7]), .P8(p36[8]), .P9(p36[9]), .P10(p36[10]), .P11(p36[11]),
            .P12(p36[12]), .P13(p36[13]), .P14(p36[14]), .P15(p36[15]), .P16(p36[16]), .P17(p36[17]),
            .P18(p36[18]), .P19(p36[19]), .P20(p36[20]), .P21(p36[21]), .P22(p36[22]), .P23(p36[23]),
            .P24(p36[24]), .P25(p36[25]), .P26(p36[26]), .P27(p36[27]), .P28(p36[28]), .P29(p36[29]),
            .P30(p36[30]), .P31(p36[31]), .P32(p36[32]), .P33(p36[33]), .P34(p36[34]), .P35(p36[35])
        );
        // |a b| < 2^(2W-2) + 1: the low 2W bits of the 36-bit product are the exact product
        always @* prod = p36[2*W-1:0];
`else
        // stage 1: the operands registered; stage 2: their product in one block, registered
        reg signed [W-1:0] a_s1, b_s1;
        always @(posedge clk) begin
            a_s1 <= a;
            b_s1 <= b;
            prod <= a_s1 * b_s1;
        end
`endif
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
