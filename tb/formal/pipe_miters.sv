// pipe_miters - each pipelined unit against its serial unit (a miter): the same operands
// into both, the results compared. Run by tb/formal/pipes.sby.
//
// The serial unit takes a start whenever the solver likes (and reset too); the pipelined
// unit takes a new operand every clock, the serial one's operands when it starts and
// anything at all otherwise. Each operation the serial unit accepts must come out of the
// pipelined unit exactly its header's latency later, bit for bit the serial result (root,
// quotient, flags; for fx_mul_pipe the exact product of fx_mul). Because the operation
// compared may start in any cycle, with any operands before and after it, this also shows
// that the pipeline takes one operand per clock and neither drops, repeats nor mixes one.
`default_nettype none

// fx_sqrt_pipe against fx_sqrt: the pipe's result is there SQRT_BITS + 3 cycles after the
// cycle its radicand was on the input; fx_sqrt's done comes SQRT_BITS + 2 cycles after.
module sqrt_miter #(
    parameter integer W         = 8,
    parameter integer SQRT_BITS = W - 1
) (
    input wire           clk,
    input wire           reset,
    input wire           start,
    input wire [2*W-1:0] radicand
);
    localparam integer LAT_S = SQRT_BITS + 2;
    localparam integer LAT_P = SQRT_BITS + 3;

    wire         busy, done, sat_s, sat_p;
    wire [W-1:0] res_s, res_p;
    fx_sqrt #(.W(W), .SQRT_BITS(SQRT_BITS)) u_serial (
        .clk(clk), .reset(reset), .start(start), .radicand(radicand),
        .busy(busy), .done(done), .result(res_s), .sat(sat_s));
    fx_sqrt_pipe #(.W(W), .SQRT_BITS(SQRT_BITS)) u_pipe (
        .clk(clk), .radicand(radicand), .result(res_p), .sat(sat_p));

    reg f_init = 1'b1;
    always @(posedge clk) f_init <= 1'b0;
    always @* if (f_init) assume (reset);

    wire            accept = start && !busy && !reset;
    reg [LAT_P-1:0] pend;
    reg [W-1:0]     res_q;
    reg             sat_q;
    always @(posedge clk) begin
        pend <= reset ? {LAT_P{1'b0}} : {pend[LAT_P-2:0], accept};
        if (done) begin
            res_q <= res_s;
            sat_q <= sat_s;
        end
    end
    always @* if (!f_init) begin
        if (pend[LAT_S-1] && !reset) assert (done);
        if (pend[LAT_P-1]) assert (res_p == res_q && sat_p == sat_q);
        cover (pend[LAT_P-1] && sat_p);
    end
endmodule

// fx_div_pipe against fx_div: DIV_BITS + 3 and DIV_BITS + 2 cycles.
module div_miter #(
    parameter integer W        = 8,
    parameter integer F        = 4,
    parameter integer DIV_BITS = W - 1
) (
    input wire         clk,
    input wire         reset,
    input wire         start,
    input wire [W-1:0] num,
    input wire [W-1:0] den
);
    localparam integer LAT_S = DIV_BITS + 2;
    localparam integer LAT_P = DIV_BITS + 3;

    wire         busy, done, sat_s, sat_p, dbz_s, dbz_p;
    wire [W-1:0] res_s, res_p;
    fx_div #(.W(W), .F(F), .DIV_BITS(DIV_BITS)) u_serial (
        .clk(clk), .reset(reset), .start(start), .num(num), .den(den),
        .busy(busy), .done(done), .result(res_s), .div_by_zero(dbz_s), .sat(sat_s));
    fx_div_pipe #(.W(W), .F(F), .DIV_BITS(DIV_BITS)) u_pipe (
        .clk(clk), .num(num), .den(den), .result(res_p), .div_by_zero(dbz_p), .sat(sat_p));

    reg f_init = 1'b1;
    always @(posedge clk) f_init <= 1'b0;
    always @* if (f_init) assume (reset);

    wire            accept = start && !busy && !reset;
    reg [LAT_P-1:0] pend;
    reg [W-1:0]     res_q;
    reg             sat_q, dbz_q;
    always @(posedge clk) begin
        pend <= reset ? {LAT_P{1'b0}} : {pend[LAT_P-2:0], accept};
        if (done) begin
            res_q <= res_s;
            sat_q <= sat_s;
            dbz_q <= dbz_s;
        end
    end
    always @* if (!f_init) begin
        if (pend[LAT_S-1] && !reset) assert (done);
        if (pend[LAT_P-1]) assert (res_p == res_q && sat_p == sat_q && dbz_p == dbz_q);
        cover (pend[LAT_P-1] && dbz_p);
    end
endmodule

// fx_mul_pipe against fx_mul's exact product: a and b in cycle 0, prod in cycle 2.
module mul_miter #(
    parameter integer W           = 8,
    parameter integer ONE_BLOCK_W = 18  // 0: the three-product split at this width
) (
    input wire         clk,
    input wire [W-1:0] a,
    input wire [W-1:0] b
);
    wire [2*W-1:0] prod_s, prod_p;
    /* the rounded outputs are fx_round's, proven in fx_mul.sby */
    wire [W-1:0]   y_unused;
    wire           sat_unused;
    fx_mul #(.W(W), .F(1)) u_serial (.a(a), .b(b), .y(y_unused), .sat(sat_unused), .prod(prod_s));
    fx_mul_pipe #(.W(W), .ONE_BLOCK_W(ONE_BLOCK_W)) u_pipe (.clk(clk), .a(a), .b(b), .prod(prod_p));

    reg [1:0]     age = 2'd0;                    // cycles since the start of the trace, to 2
    reg [2*W-1:0] p1, p2;
    always @(posedge clk) begin
        if (age != 2'd2) age <= age + 2'd1;
        p1 <= prod_s;
        p2 <= p1;
    end
    always @* if (age == 2'd2) assert (prod_p == p2);
endmodule

`resetall
