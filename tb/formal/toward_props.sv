// toward_props - the datapaths rtl/toward.v and rtl/toward_pipe.v. Run by
// tb/formal/toward.sby. Three tops:
//   toward_hs      toward's handshake: with start free, done is high exactly LATENCY
//                  (toward_latency) cycles after an accepted start (start
//                  while busy is low), for one cycle, and at no other time; busy in the
//                  cycles between; both low after a reset.
//   toward_pipe_vt toward_pipe's valid bits and tags: out_valid is in_valid exactly
//                  LATENCY (toward_pipe_latency) cycles earlier (since reset: an
//                  operation a clock, none dropped, none repeated), and out_tag is its tag;
//                  out_valid low after a reset.
//   toward_miter   toward_pipe against toward: one operation (P, C, rest, rule: one arbitrary
//                  value) into both in the second cycle after reset, any other traffic into
//                  the pipe before and after it; the pipe's out_t and out_ok for it equal
//                  toward's t and valid. (One start cycle: each compared cycle costs the
//                  solver minutes, the root, divider and multipliers of both datapaths.)
// The latencies are rtl/pipe_latency.vh's and tb/serial_latency.vh's (checked against model/timing.c by
// units-latency-formulas); the checkers tb/serial_latency_check.v and tb/formal/pipe_vt_check.sv.
`default_nettype none

module toward_hs #(
    parameter integer W = 8, parameter integer F = 4, parameter integer SQRT_BITS = 1,
    parameter integer DIV_BITS = 1, parameter integer DIM = 2
) (
    input wire clk, input wire reset, input wire start, input wire excess,
    input wire [DIM*W-1:0] p, input wire [DIM*W-1:0] c, input wire [W-1:0] rest_len
);
`include "pipe_latency.vh"
`include "serial_latency.vh"
    localparam integer LAT = toward_latency(SQRT_BITS, DIV_BITS, DIM, 1, 0, 0);
    wire busy, done, valid;
    wire [DIM*W-1:0] t;
    toward #(.W(W), .F(F), .SQRT_BITS(SQRT_BITS), .DIV_BITS(DIV_BITS), .DIM(DIM)) dut (
        .clk(clk), .reset(reset), .start(start), .excess(excess), .p(p), .c(c), .rest_len(rest_len),
        .busy(busy), .done(done), .t(t), .valid(valid));
    serial_latency_check #(.DEPTH(LAT)) chk (.clk(clk), .reset(reset), .latency(LAT[15:0]), .start(start), .busy(busy),
                                             .done(done), .violations());
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
`include "pipe_latency.vh"
`include "serial_latency.vh"
    localparam integer LAT = toward_pipe_latency(SQRT_BITS, DIV_BITS, 1, 0);
    wire out_valid, out_ok;
    wire [DIM*W-1:0] out_t, out_p, out_c;
    wire [TAG_W-1:0] out_tag;
    toward_pipe #(.W(W), .F(F), .SQRT_BITS(SQRT_BITS), .DIV_BITS(DIV_BITS), .DIM(DIM), .TAG_W(TAG_W),
                  .CARRY(CARRY)) dut (
        .clk(clk), .reset(reset), .in_valid(in_valid), .in_excess(in_excess), .in_p(in_p), .in_c(in_c),
        .in_rest(in_rest), .in_tag(in_tag), .out_valid(out_valid), .out_t(out_t), .out_ok(out_ok),
        .out_tag(out_tag), .out_p(out_p), .out_c(out_c));
    pipe_vt_check #(.LAT(LAT), .TAG_W(TAG_W)) chk (.clk(clk), .reset(reset), .in_valid(in_valid), .in_tag(in_tag),
                                                   .out_valid(out_valid), .out_tag(out_tag));
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
`include "pipe_latency.vh"
`include "serial_latency.vh"
    localparam integer LAT_S = toward_latency(SQRT_BITS, DIV_BITS, DIM, 1, 0, 0);
    localparam integer LAT_P = toward_pipe_latency(SQRT_BITS, DIV_BITS, 1, 0);
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
