// round_check - the rounding properties fx_mul_props and fx_round_props share (combinational;
// asserts only): y is prod / 2^F rounded to the nearest integer, ties to even, i.e. in integers
//     |2 (prod - y 2^F)| <= 2^F,  and when equal (a tie) y is even,
// unless that does not fit W bits: sat = 1 exactly when
//     prod >= (2^W - 1) 2^(F-1)       (at or above max + 1/2: max is odd, the tie goes up)
//     prod <  -(2^W + 1) 2^(F-1)      (below min - 1/2: min is even, the tie stays)
// and then y is the maximum or the minimum. prod is any signed 2W-bit value.
`default_nettype none

module round_check #(
    parameter integer W = 8,
    parameter integer F = 4
) (
    input wire [2*W-1:0] prod,
    input wire [W-1:0]   y,
    input wire           sat
);
    localparam integer PW = 2 * W + 2;        // wide enough for prod and the bounds

    wire signed [PW-1:0] p    = $signed(prod);
    wire signed [PW-1:0] ys   = $signed(y);
    wire signed [PW-1:0] err2 = 2 * (p - ys * (2 ** F));        // 2 (prod - y 2^F)
    wire signed [PW-1:0] one  = 2 ** F;
    wire signed [PW-1:0] hi   = ((2 ** W) - 1) * (2 ** (F - 1));
    wire signed [PW-1:0] lo   = -(((2 ** W) + 1) * (2 ** (F - 1)));

    always @* begin
        assert (sat == (p >= hi || p < lo));
        if (p >= hi) assert (y == {1'b0, {(W-1){1'b1}}});
        if (p < lo)  assert (y == {1'b1, {(W-1){1'b0}}});
        if (!sat) begin
            assert (err2 <= one && err2 >= -one);
            if (err2 == one || err2 == -one) assert (y[0] == 1'b0);
        end
        cover (!sat && err2 == one);
        cover (!sat && err2 == -one);
        cover (sat && p == hi);
    end
endmodule

`resetall
