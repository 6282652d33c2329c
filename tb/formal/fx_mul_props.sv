// fx_mul_props - formal properties of rtl/fx_mul.v and rtl/fx_round.v (combinational; a
// wrapper top with free a and b). Run by tb/formal/fx_mul.sby.
//
// Checked against what the rounded product is (fx_mul.v and fx_round.v headers, fx_mul()
// of model/fixed.h), not against the algorithm: prod = a b exactly (2W bits, signed);
// y is prod / 2^F rounded to nearest, ties to even, saturated (tb/formal/round_check.sv
// states it).
`default_nettype none

module fx_mul_props #(
    parameter integer W = 8,
    parameter integer F = 4
) (
    input wire [W-1:0] a,
    input wire [W-1:0] b
);
    localparam integer PW = 2 * W + 2;        // wide enough for the product

    wire [W-1:0]   y;
    wire           sat;
    wire [2*W-1:0] prod;
    fx_mul #(.W(W), .F(F)) dut (.a(a), .b(b), .y(y), .sat(sat), .prod(prod));
    // the rounding of that product (tb/formal/round_check.sv)
    round_check #(.W(W), .F(F)) check (.prod(prod), .y(y), .sat(sat));

    wire signed [PW-1:0] pa = $signed(a);
    wire signed [PW-1:0] pb = $signed(b);
    wire signed [PW-1:0] p  = pa * pb;                          // the exact product

    always @* assert ($signed(prod) == p);
endmodule

`resetall
