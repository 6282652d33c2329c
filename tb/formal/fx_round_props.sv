// fx_round_props - formal properties of rtl/fx_round.v on its own (combinational; a wrapper
// top with a free 2W-bit prod). Run by tb/formal/fx_mul.sby (tasks round_*).
//
// fx_mul_props checks fx_round on the products of two W-bit values only. The spring's
// datapaths also round a clamped sum of two products (up to 2^(2W-1) - 1, which no single
// product reaches), so here prod is every 2W-bit value, against the same rounding
// properties (tb/formal/round_check.sv).
`default_nettype none

module fx_round_props #(
    parameter integer W = 8,
    parameter integer F = 4
) (
    input wire [2*W-1:0] prod
);
    wire [W-1:0] y;
    wire         sat;
    fx_round #(.W(W), .F(F)) dut (.prod(prod), .y(y), .sat(sat));
    round_check #(.W(W), .F(F)) check (.prod(prod), .y(y), .sat(sat));

    always @* cover (sat && prod == {1'b0, {(2*W-1){1'b1}}});   // the largest: a clamped sum
endmodule

`resetall
