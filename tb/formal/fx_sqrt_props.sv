// fx_sqrt_props - formal properties of rtl/fx_sqrt.v (a wrapper top: the unit with free
// inputs, and the checks around it). Run by tb/formal/fx_sqrt.sby.
//
// The result is checked against what a root is, not against the algorithm. With
// M = W-1 magnitude bits, LSB = M - SQRT_BITS and L = 2^LSB, fx_sqrt.v's header and
// fx_sqrt() of model/fixed.c say: the root of x rounded to the nearest multiple of L, an
// exact half rounding up, clamped to 2^M - 1 with sat. For a multiple r of L that is
//     (r - L/2)^2 <= x < (r + L/2)^2,  in integers  (2r - L)^2 <= 4x < (2r + L)^2
// (the lower bound only for r > 0): these intervals cover 0 .. inf without overlap, so
// the property fixes r. The rounded root does not fit (sat) exactly when
//     sqrt(x) >= 2^M - L/2,  4x >= (2^(M+1) - L)^2,
// and then result = 2^M - 1.
//
// Handshake (the header's timing): start seen while busy is low is accepted; busy is high
// in the SQRT_BITS+1 cycles after, done in the one cycle after those, and at no other
// time; no start is accepted while busy; result and sat change only in a done cycle.
// Reset: from the first cycle after a reset, busy, done, result and sat are 0.
`default_nettype none

module fx_sqrt_props #(
    parameter integer W         = 8,
    parameter integer SQRT_BITS = W - 1
) (
    input wire           clk,
    input wire           reset,
    input wire           start,
    input wire [2*W-1:0] radicand
);
    localparam integer M   = W - 1;
    localparam integer LSB = M - SQRT_BITS;
`include "pipe_latency.vh"
`include "serial_latency.vh"
    localparam integer  LAT   = sqrt_latency(SQRT_BITS);   // the start cycle to the done cycle (model/timing.c's)
    localparam [15:0]   LAT16 = LAT[15:0];
    localparam integer XW  = 2 * W + 4;       // wide enough for (2^(M+1) + L)^2 and 4x

    wire         busy, done, sat;
    wire [W-1:0] result;

    fx_sqrt #(.W(W), .SQRT_BITS(SQRT_BITS)) dut (
        .clk(clk), .reset(reset), .start(start), .radicand(radicand),
        .busy(busy), .done(done), .result(result), .sat(sat));

    // the first cycle is a reset cycle
    reg f_init = 1'b1;
    always @(posedge clk) f_init <= 1'b0;
    always @* if (f_init) assume (reset);

    // ---- the handshake: the latency contract (tb/serial_latency_check.v, the unit benches' too) ----
    serial_latency_check #(.DEPTH(LAT)) contract (.clk(clk), .reset(reset), .latency(LAT16), .start(start),
                                                  .busy(busy), .done(done), .violations());
    wire          accept = start && !busy && !reset;
    reg [2*W-1:0] x_q;                      // the radicand of the operation in flight
    always @(posedge clk) if (accept) x_q <= radicand;

    reg [W-1:0] result_prev;
    reg         sat_prev, reset_prev;
    always @(posedge clk) begin
        result_prev <= result;
        sat_prev    <= sat;
        reset_prev  <= reset;
    end

    always @* if (!f_init) begin
        if (reset_prev) assert (result == {W{1'b0}} && !sat);
        else if (!done) assert (result == result_prev && sat == sat_prev);
    end

    // ---- the result: a rounded root ----
    localparam [XW-1:0] L      = {{(XW-1){1'b0}}, 1'b1} << LSB;
    localparam [XW-1:0] TOP    = {{(XW-1){1'b0}}, 1'b1} << (M + 1);   // 2^(M+1)
    localparam [XW-1:0] MAXR   = ({{(XW-1){1'b0}}, 1'b1} << M) - 1;   // 2^M - 1
    wire [XW-1:0] x4     = {{(XW-2*W-2){1'b0}}, x_q, 2'b00};
    wire [XW-1:0] r      = {{(XW-W){1'b0}}, result};
    wire [XW-1:0] lo     = 2 * r - L;
    wire [XW-1:0] hi     = 2 * r + L;
    wire          too_big = x4 >= (TOP - L) * (TOP - L);

    always @* if (!f_init && !reset_prev && done) begin
        assert (sat == too_big);
        if (sat) begin
            assert (r == MAXR);
        end else begin
            assert (r[M] == 1'b0);
            assert ((r & (L - 1)) == 0);
            assert (x4 < hi * hi);
            if (r != 0) assert (lo * lo <= x4);
        end
    end

    // reachability: an operation completes, one saturates, one is exact at a half
    always @* if (!f_init && !reset_prev && done) begin
        cover (sat);
        cover (!sat && r != 0 && lo * lo == x4);
    end
endmodule

`resetall
