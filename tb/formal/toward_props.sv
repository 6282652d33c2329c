// toward_props - the datapaths rtl/toward.v and rtl/toward_pipe.v. Run by
// tb/formal/toward.sby. Three tops:
//   toward_hs      toward's handshake: with start free, done is high exactly LATENCY =
//                  SQRT_BITS + DIV_BITS + 2 DIM + 10 cycles after an accepted start (start
//                  while busy is low), for one cycle, and at no other time; busy in the
//                  cycles between; both low after a reset.
//   toward_pipe_vt toward_pipe's valid bits and tags: out_valid is in_valid exactly
//                  LATENCY = SQRT_BITS + DIV_BITS + 15 cycles earlier (since reset: an
//                  operation a clock, none dropped, none repeated), and out_tag is its tag;
//                  out_valid low after a reset.
//   toward_miter   toward_pipe against toward: one operation (P, C, rest, rule: one arbitrary
//                  value) into both in the second cycle after reset, any other traffic into
//                  the pipe before and after it; the pipe's out_t and out_ok for it equal
//                  toward's t and valid. (One start cycle: each compared cycle costs the
//                  solver minutes, the root, divider and multipliers of both datapaths.)
`default_nettype none

module toward_hs #(
    parameter integer W = 8, parameter integer F = 4, parameter integer SQRT_BITS = 1,
    parameter integer DIV_BITS = 1, parameter integer DIM = 2
) (
    input wire clk, input wire reset, input wire start, input wire excess,
    input wire [DIM*W-1:0] p, input wire [DIM*W-1:0] c, input wire [W-1:0] rest_len
);
    localparam integer LAT = SQRT_BITS + DIV_BITS + 2 * DIM + 10;
    wire busy, done, valid;
    wire [DIM*W-1:0] t;
    toward #(.W(W), .F(F), .SQRT_BITS(SQRT_BITS), .DIV_BITS(DIV_BITS), .DIM(DIM)) dut (
        .clk(clk), .reset(reset), .start(start), .excess(excess), .p(p), .c(c), .rest_len(rest_len),
        .busy(busy), .done(done), .t(t), .valid(valid));
    reg f_init = 1'b1;
    always @(posedge clk) f_init <= 1'b0;
    always @* if (f_init) assume (reset);
    wire accept = start && !busy && !reset;
    reg [LAT-1:0] pend;
    reg reset_prev;
    always @(posedge clk) begin
        pend <= reset ? {LAT{1'b0}} : {pend[LAT-2:0], accept};
        reset_prev <= reset;
    end
    always @* if (!f_init) begin
        if (reset_prev) assert (!busy && !done);
        else begin
            assert (done == pend[LAT-1]);
            assert (busy == |pend[LAT-2:0]);
            assert ($onehot0(pend));
        end
        cover (done);
    end
    wire unused = &{1'b0, t, valid};
endmodule

module toward_pipe_vt #(
    parameter integer W = 8, parameter integer F = 4, parameter integer SQRT_BITS = 1,
    parameter integer DIV_BITS = 1, parameter integer DIM = 2, parameter integer TAG_W = 3,
    parameter [0:0] CARRY = 1'b0
) (
    input wire clk, input wire reset, input wire in_valid, input wire in_excess,
    input wire [DIM*W-1:0] in_p, input wire [DIM*W-1:0] in_c, input wire [W-1:0] in_rest,
    input wire [TAG_W-1:0] in_tag
);
    localparam integer LAT = SQRT_BITS + DIV_BITS + 15;
    wire out_valid, out_ok;
    wire [DIM*W-1:0] out_t, out_p, out_c;
    wire [TAG_W-1:0] out_tag;
    toward_pipe #(.W(W), .F(F), .SQRT_BITS(SQRT_BITS), .DIV_BITS(DIV_BITS), .DIM(DIM), .TAG_W(TAG_W),
                  .CARRY(CARRY)) dut (
        .clk(clk), .reset(reset), .in_valid(in_valid), .in_excess(in_excess), .in_p(in_p), .in_c(in_c),
        .in_rest(in_rest), .in_tag(in_tag), .out_valid(out_valid), .out_t(out_t), .out_ok(out_ok),
        .out_tag(out_tag), .out_p(out_p), .out_c(out_c));
    reg f_init = 1'b1;
    always @(posedge clk) f_init <= 1'b0;
    always @* if (f_init) assume (reset);
    // what went in, LAT cycles ago: a valid bit (0 across a reset) and a tag
    reg [LAT-1:0]   v_in;
    reg [TAG_W-1:0] tag_in [0:LAT-1];
    reg             reset_prev;
    integer i;
    always @(posedge clk) begin
        v_in <= reset ? {LAT{1'b0}} : {v_in[LAT-2:0], in_valid};
        tag_in[0] <= in_tag;
        for (i = 1; i < LAT; i = i + 1) tag_in[i] <= tag_in[i-1];
        reset_prev <= reset;
    end
    always @* if (!f_init) begin
        if (reset_prev) assert (!out_valid);
        else assert (out_valid == v_in[LAT-1]);
        if (out_valid && !reset_prev) assert (out_tag == tag_in[LAT-1]);
        cover (out_valid);
    end
    wire unused = &{1'b0, out_t, out_ok, out_p, out_c};
endmodule

module toward_miter #(
    parameter integer W = 8, parameter integer F = 4, parameter integer SQRT_BITS = 1,
    parameter integer DIV_BITS = 1, parameter integer DIM = 2
) (
    input wire clk, input wire reset,
    input wire in_valid, input wire in_excess,
    input wire [DIM*W-1:0] in_p, input wire [DIM*W-1:0] in_c, input wire [W-1:0] in_rest
);
    localparam integer LAT_S = SQRT_BITS + DIV_BITS + 2 * DIM + 10;
    localparam integer LAT_P = SQRT_BITS + DIV_BITS + 15;
    (* anyconst *) reg [DIM*W-1:0] op_p, op_c;
    (* anyconst *) reg [W-1:0]     op_rest;
    (* anyconst *) reg             op_excess;
    reg f_init = 1'b1;
    reg [1:0] cyc = 2'd0;                            // cycles since the reset cycle, to 3
    always @(posedge clk) begin
        f_init <= 1'b0;
        if (cyc != 2'd3) cyc <= cyc + 2'd1;
    end
    always @* assume (reset == f_init);
    wire start = cyc == 2'd2;                        // the one operation

    wire busy, done, valid, out_valid, out_ok;
    wire [DIM*W-1:0] t, out_t, out_p, out_c;
    wire [0:0] out_tag;
    toward #(.W(W), .F(F), .SQRT_BITS(SQRT_BITS), .DIV_BITS(DIV_BITS), .DIM(DIM)) u_serial (
        .clk(clk), .reset(reset), .start(start), .excess(op_excess), .p(op_p), .c(op_c), .rest_len(op_rest),
        .busy(busy), .done(done), .t(t), .valid(valid));
    toward_pipe #(.W(W), .F(F), .SQRT_BITS(SQRT_BITS), .DIV_BITS(DIV_BITS), .DIM(DIM), .TAG_W(1)) u_pipe (
        .clk(clk), .reset(reset), .in_valid(start ? 1'b1 : in_valid), .in_excess(start ? op_excess : in_excess),
        .in_p(start ? op_p : in_p), .in_c(start ? op_c : in_c), .in_rest(start ? op_rest : in_rest),
        .in_tag(start), .out_valid(out_valid), .out_t(out_t), .out_ok(out_ok), .out_tag(out_tag),
        .out_p(out_p), .out_c(out_c));
    reg [LAT_P-1:0] pend;
    reg [DIM*W-1:0] t_q;
    reg             valid_q;
    always @(posedge clk) begin
        pend <= reset ? {LAT_P{1'b0}} : {pend[LAT_P-2:0], start};
        if (done) begin
            t_q     <= t;
            valid_q <= valid;
        end
    end
    always @* if (!f_init) begin
        if (pend[LAT_S-1]) assert (done);
        if (pend[LAT_P-1]) assert (out_valid && out_tag == 1'b1 && out_ok == valid_q && (!valid_q || out_t == t_q));
        cover (pend[LAT_P-1] && valid_q);
    end
    wire unused = &{1'b0, busy, out_p, out_c};
endmodule

`resetall
