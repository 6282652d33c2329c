// fx_div_props - formal properties of rtl/fx_div.v (a wrapper top: the unit with free
// inputs, and the checks around it). Run by tb/formal/fx_div.sby.
//
// The result is checked against what a quotient is, not against the algorithm. With
// M = W-1 magnitude bits, LSB = M - DIV_BITS, L = 2^LSB and the dividend D = num 2^F,
// fx_div.v's header and fx_div() of model/fixed.c say: D / den rounded to the nearest
// multiple of L, an exact half rounding up, clamped to 2^M - 1 with sat. For a multiple r
// of L that is
//     r - L/2 <= D / den < r + L/2,  in integers  (2r - L) den <= 2D < (2r + L) den
// (the lower bound only for r > 0), which fixes r. The rounded quotient does not fit
// (sat) exactly when 2D >= (2^(M+1) - L) den. den = 0 gives div_by_zero = 1, sat = 0 and
// result = 2^M - 1.
//
// Handshake, reset: as fx_sqrt_props.sv (the same timing with DIV_BITS).
//
// RESULT = 1 checks the result with num and den held at one arbitrary pair for the whole
// run (anyconst: every pair is tried, one per proof run; the solver keeps what it learns
// from one step to the next); RESULT = 0 checks the handshake with operands that change
// at will.
`default_nettype none

module fx_div_props #(
    parameter integer W        = 8,
    parameter integer F        = 4,
    parameter integer DIV_BITS = W - 1,
    parameter [0:0]   RESULT   = 1'b1
) (
    input wire         clk,
    input wire         reset,
    input wire         start,
    input wire [W-1:0] num_in,
    input wire [W-1:0] den_in
);
    (* anyconst *) reg [W-1:0] num_c, den_c;
    wire [W-1:0] num = RESULT ? num_c : num_in;
    wire [W-1:0] den = RESULT ? den_c : den_in;

    localparam integer M   = W - 1;
    localparam integer LSB = M - DIV_BITS;
`include "pipe_latency.vh"
`include "serial_latency.vh"
    localparam integer LAT   = div_latency(DIV_BITS);   // the start cycle to the done cycle (model/timing.c's)
    localparam [15:0]  LAT16 = LAT[15:0];
    localparam integer XW  = 2 * W + 2;       // wide enough for (2r + L) den < 2^(2W+1) and 2 num 2^F

    wire         busy, done, sat, dbz;
    wire [W-1:0] result;

    fx_div #(.W(W), .F(F), .DIV_BITS(DIV_BITS)) dut (
        .clk(clk), .reset(reset), .start(start), .num(num), .den(den),
        .busy(busy), .done(done), .result(result), .div_by_zero(dbz), .sat(sat));

    reg f_init = 1'b1;
    always @(posedge clk) f_init <= 1'b0;
    always @* if (f_init) assume (reset);

    // ---- the handshake: the latency contract (tb/serial_latency_check.v, the unit benches' too) ----
    serial_latency_check #(.DEPTH(LAT)) contract (.clk(clk), .reset(reset), .latency(LAT16), .start(start),
                                                  .busy(busy), .done(done), .violations());
    wire          accept = start && !busy && !reset;
    reg [W-1:0]   num_q, den_q;             // the operands of the operation in flight
    always @(posedge clk)
        if (accept) begin
            num_q <= num;
            den_q <= den;
        end

    reg [W-1:0] result_prev;
    reg         sat_prev, dbz_prev, reset_prev;
    always @(posedge clk) begin
        result_prev <= result;
        sat_prev    <= sat;
        dbz_prev    <= dbz;
        reset_prev  <= reset;
    end

    always @* if (!f_init) begin
        if (reset_prev) assert (result == {W{1'b0}} && !sat && !dbz);
        else if (!done) assert (result == result_prev && sat == sat_prev && dbz == dbz_prev);
    end

    // ---- the result: a rounded quotient ----
    localparam [XW-1:0] L    = {{(XW-1){1'b0}}, 1'b1} << LSB;
    localparam [XW-1:0] TOP  = {{(XW-1){1'b0}}, 1'b1} << (M + 1);   // 2^(M+1)
    localparam [XW-1:0] MAXR = ({{(XW-1){1'b0}}, 1'b1} << M) - 1;   // 2^M - 1
    wire [XW-1:0] d2      = {{(XW-W){1'b0}}, num_q} << (F + 1);     // 2 D
    wire [XW-1:0] dv      = {{(XW-W){1'b0}}, den_q};
    wire [XW-1:0] r       = {{(XW-W){1'b0}}, result};
    wire          too_big = d2 >= (TOP - L) * dv;

    always @* if (RESULT && !f_init && !reset_prev && done) begin
        assert (dbz == (den_q == {W{1'b0}}));
        if (dbz) begin
            assert (r == MAXR && !sat);
        end else begin
            assert (sat == too_big);
            if (sat) begin
                assert (r == MAXR);
            end else begin
                assert (r[M] == 1'b0);
                assert ((r & (L - 1)) == 0);
                assert (d2 < (2 * r + L) * dv);
                if (r != 0) assert ((2 * r - L) * dv <= d2);
            end
        end
    end

    always @* if (!f_init && !reset_prev && done) begin
        cover (dbz);
        cover (sat);
        cover (!sat && !dbz && r != 0 && (2 * r - L) * dv == d2);   // an exact half, rounded up
    end
endmodule

`resetall
