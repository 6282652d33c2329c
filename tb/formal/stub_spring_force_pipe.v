// stub_spring_force_pipe - a stand-in for rtl/spring_force_pipe.v in the proof of
// spring_stream (tb/formal/spring_stream.sby): the same ports; out_valid and out_tag are
// in_valid and in_tag LATENCY = spring_pipe_latency() cycles later (rtl/pipe_latency.vh: what
// spring_force_pipe's header promises, and tb/formal/datapaths.sby checks of it), and
// out_f and out_ok are known functions of the operands: f = a - b + (ap ^ bp) lane by
// lane (wrapping), ok = (a != b) (a zero length has no force), so the checker can tell
// which nodes a force was computed from; the real force's arithmetic is the datapath's
// own proof.
`default_nettype none

module spring_force_pipe #(
    parameter integer W         = 32,
    parameter integer F         = 16,
    parameter integer SQRT_BITS = W - 1,
    parameter integer DIV_BITS  = W - 1,
    parameter integer MANTISSA  = 0,
    parameter integer STEPS     = 1,
    parameter integer DIM       = 2,
    parameter integer TAG_W     = 1,
    parameter integer BLOCK_MIN = 64
) (
    input  wire             clk,
    input  wire             reset,
    input  wire             in_valid,
    input  wire [DIM*W-1:0] in_a,
    input  wire [DIM*W-1:0] in_ap,
    input  wire [DIM*W-1:0] in_b,
    input  wire [DIM*W-1:0] in_bp,
    input  wire [W-1:0]     in_rest,
    input  wire [W-1:0]     in_ks,
    input  wire [W-1:0]     in_kd,
    input  wire [TAG_W-1:0] in_tag,
    output wire             out_valid,
    output reg  [DIM*W-1:0] out_f,
    output reg              out_ok,
    output wire [TAG_W-1:0] out_tag
);
`include "pipe_latency.vh"
    localparam integer LATENCY = spring_pipe_latency(SQRT_BITS, DIV_BITS, STEPS, MANTISSA);
    // delay lines as flat shift registers (no memories: the abc engines take no x bits)
    reg [LATENCY-1:0]         v_q, ok_q;
    reg [LATENCY*TAG_W-1:0]   tag_q;
    reg [LATENCY*DIM*W-1:0]   f_q;
    reg [DIM*W-1:0]   f_in;
    integer i;
    always @* for (i = 0; i < DIM; i = i + 1)
        f_in[i*W +: W] = in_a[i*W +: W] - in_b[i*W +: W] + (in_ap[i*W +: W] ^ in_bp[i*W +: W]);
    always @(posedge clk) begin
        v_q <= reset ? {LATENCY{1'b0}} : {v_q[LATENCY-2:0], in_valid};
        ok_q  <= {ok_q[LATENCY-2:0], in_a != in_b};
        tag_q <= {tag_q[(LATENCY-1)*TAG_W-1:0], in_tag};
        f_q   <= {f_q[(LATENCY-1)*DIM*W-1:0], f_in};
    end
    always @* begin
        out_f  = f_q[(LATENCY-1)*DIM*W +: DIM*W];
        out_ok = ok_q[LATENCY-1];
    end
    assign out_valid = v_q[LATENCY-1];
    assign out_tag   = tag_q[(LATENCY-1)*TAG_W +: TAG_W];
    wire unused = &{1'b0, in_rest, in_ks, in_kd, BLOCK_MIN[0], F[0]};
endmodule

`resetall
