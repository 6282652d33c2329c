// stub_toward_pipe - a stand-in for rtl/toward_pipe.v in the proof of chain_stream
// (tb/formal/stream.sby): the same ports; out_valid and out_tag are in_valid and in_tag
// LATENCY = toward_pipe_latency() cycles later (in_tag one cycle less with IN_REG = 0, as it
// comes a cycle after in_valid) (rtl/pipe_latency.vh: what toward_pipe's header promises,
// and tb/formal/toward.sby checks of toward_pipe), and out_t, out_ok, out_p, out_c are
// chosen by the solver. The sweep's order and timing are then checked for any data.
`default_nettype none

module toward_pipe #(
    parameter integer W         = 32,
    parameter integer F         = 16,
    parameter integer SQRT_BITS = W - 1,
    parameter integer DIV_BITS  = W - 1,
    parameter integer MANTISSA  = 0,
    parameter integer STEPS     = 1,
    parameter integer DIM       = 2,
    parameter integer TAG_W     = 1,
    parameter [0:0]   CARRY     = 1'b0,
    parameter [0:0]   IN_REG    = 1'b1,   // 0: in_tag (and the data) a cycle after in_valid
    parameter integer BLOCK_MIN = 64
) (
    input  wire             clk,
    input  wire             reset,
    input  wire             in_valid,
    input  wire             in_excess,
    input  wire [DIM*W-1:0] in_p,
    input  wire [DIM*W-1:0] in_c,
    input  wire [W-1:0]     in_rest,
    input  wire [TAG_W-1:0] in_tag,
    output wire             out_valid,
    output reg  [DIM*W-1:0] out_t,
    output reg              out_ok,
    output reg  [TAG_W-1:0] out_tag,
    output wire [DIM*W-1:0] out_p,
    output wire [DIM*W-1:0] out_c
);
`include "pipe_latency.vh"
    localparam integer LATENCY = toward_pipe_latency(SQRT_BITS, DIV_BITS, STEPS, MANTISSA);
    reg [LATENCY-1:0] v_q;
    reg [TAG_W-1:0]   tag_q [0:LATENCY-1];
    integer i;
    always @(posedge clk) begin
        v_q <= reset ? {LATENCY{1'b0}} : {v_q[LATENCY-2:0], in_valid};
        tag_q[0] <= in_tag;
        for (i = 1; i < LATENCY; i = i + 1) tag_q[i] <= tag_q[i-1];
    end
    // the tag of the operation in_valid marks: with IN_REG = 0 it comes a cycle later
    wire [TAG_W-1:0] tag_out = IN_REG ? tag_q[LATENCY-1] : tag_q[LATENCY-2];
    (* anyseq *) reg [DIM*W-1:0] t_any, p_any, c_any;
    (* anyseq *) reg             ok_any;
    always @* begin
        out_t   = t_any;
        out_ok  = ok_any;
        out_tag = tag_out;
    end
    assign out_valid = v_q[LATENCY-1];
    assign out_p = CARRY ? p_any : {DIM*W{1'b0}};
    assign out_c = CARRY ? c_any : {DIM*W{1'b0}};
    wire unused = &{1'b0, in_excess, in_p, in_c, in_rest, BLOCK_MIN[0], F[0]};
endmodule

`resetall
