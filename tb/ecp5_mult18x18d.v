`default_nettype none
`timescale 1ns / 1ps

/*
 * ecp5_mult18x18d - a behavioural model of the ECP5 MULT18X18D for simulation, as far as
 * rtl/fx_mul_pipe.v uses it: an 18 x 18 product P = A * B (signed when SIGNEDA/SIGNEDB
 * are 1), with the A and B input registers and the output register each either absent
 * ("NONE") or clocked by CLK0 with CE0 ("CLK0"), and no pipeline register. Any other
 * configuration (the C input, the cascade, other clocks, the pipeline register) stops
 * the simulation with an error, so the model is never used beyond what it covers.
 * Yosys ships the block as a black box only (techlibs/ecp5/cells_bb.v); the registers'
 * behaviour here follows Lattice's sysDSP description (registers on the operands, on
 * the product, each adding one cycle). Only the unit bench of fx_mul_pipe's ECP5 branch
 * (tb/units.mk, STRAND_ECP5_DSP) compiles it.
 */
/* verilator lint_off DECLFILENAME */  // the module carries the vendor primitive's name
module MULT18X18D #(
/* verilator lint_on DECLFILENAME */
    parameter REG_INPUTA_CLK   = "NONE",
    parameter REG_INPUTB_CLK   = "NONE",
    parameter REG_PIPELINE_CLK = "NONE",
    parameter REG_OUTPUT_CLK   = "NONE"
) (
    input  wire A0, A1, A2, A3, A4, A5, A6, A7, A8, A9, A10, A11, A12, A13, A14, A15, A16, A17,
    input  wire B0, B1, B2, B3, B4, B5, B6, B7, B8, B9, B10, B11, B12, B13, B14, B15, B16, B17,
    input  wire C0, C1, C2, C3, C4, C5, C6, C7, C8, C9, C10, C11, C12, C13, C14, C15, C16, C17,
    input  wire SIGNEDA, SIGNEDB, SOURCEA, SOURCEB,
    input  wire CLK0, CLK1, CLK2, CLK3,
    input  wire CE0, CE1, CE2, CE3,
    input  wire RST0, RST1, RST2, RST3,
    output wire P0, P1, P2, P3, P4, P5, P6, P7, P8, P9, P10, P11, P12, P13, P14, P15, P16, P17,
    output wire P18, P19, P20, P21, P22, P23, P24, P25, P26, P27, P28, P29, P30, P31, P32, P33, P34, P35
);
    wire [17:0] a = {A17, A16, A15, A14, A13, A12, A11, A10, A9, A8, A7, A6, A5, A4, A3, A2, A1, A0};
    wire [17:0] b = {B17, B16, B15, B14, B13, B12, B11, B10, B9, B8, B7, B6, B5, B4, B3, B2, B1, B0};
    wire [17:0] c = {C17, C16, C15, C14, C13, C12, C11, C10, C9, C8, C7, C6, C5, C4, C3, C2, C1, C0};

    initial begin
        if ((REG_INPUTA_CLK != "NONE" && REG_INPUTA_CLK != "CLK0") ||
            (REG_INPUTB_CLK != "NONE" && REG_INPUTB_CLK != "CLK0") ||
            (REG_OUTPUT_CLK != "NONE" && REG_OUTPUT_CLK != "CLK0") || REG_PIPELINE_CLK != "NONE") begin
            $display("FAIL MULT18X18D model: configuration not modelled in %m");
            $fatal(1);
        end
    end
    always @* if (c !== 18'd0 || SOURCEA !== 1'b0 || SOURCEB !== 1'b0) begin
        $display("FAIL MULT18X18D model: the C input and the shift sources are not modelled in %m");
        $fatal(1);
    end

    reg  [17:0] a_q, b_q;
    reg  [35:0] p_q;
    always @(posedge CLK0) if (CE0) begin
        a_q <= a;
        b_q <= b;
    end
    wire [17:0] a_in = REG_INPUTA_CLK == "CLK0" ? a_q : a;
    wire [17:0] b_in = REG_INPUTB_CLK == "CLK0" ? b_q : b;
    // each operand extended to 36 bits by its own signedness, then a 36-bit product
    wire [35:0] a_x = {{18{SIGNEDA & a_in[17]}}, a_in};
    wire [35:0] b_x = {{18{SIGNEDB & b_in[17]}}, b_in};
    wire [35:0] p   = a_x * b_x;
    always @(posedge CLK0) if (CE0) p_q <= p;
    wire [35:0] p_out = REG_OUTPUT_CLK == "CLK0" ? p_q : p;
    assign {P35, P34, P33, P32, P31, P30, P29, P28, P27, P26, P25, P24, P23, P22, P21, P20, P19, P18,
            P17, P16, P15, P14, P13, P12, P11, P10, P9, P8, P7, P6, P5, P4, P3, P2, P1, P0} = p_out;

    wire unused = &{1'b0, CLK1, CLK2, CLK3, CE1, CE2, CE3, RST0, RST1, RST2, RST3};
endmodule

`resetall
