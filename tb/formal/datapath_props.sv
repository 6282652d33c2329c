// datapath_props - the spring and previous-projection datapaths: rtl/spring_force.v,
// rtl/spring_force_pipe.v, rtl/toward_prev.v, rtl/toward_prev_pipe.v. Run by
// tb/formal/datapaths.sby. Three kinds of top, each for both pairs:
//   *_hs     the serial unit's handshake: with start free, done is high exactly LATENCY
//            cycles after an accepted start (start while busy is low), for one cycle,
//            and at no other time; busy in the cycles between; both low after a reset.
//   *_vt     the pipelined unit's valid bits and tags: out_valid is in_valid exactly
//            LATENCY cycles earlier (since reset: one operation a clock, none dropped,
//            none repeated), and out_tag is its tag; out_valid low after a reset.
//   *_miter  the pipelined unit against the serial one: one operation (every operand one
//            arbitrary value) into both in the second cycle after reset, any other traffic
//            into the pipe before and after it; the pipe's result and flag for it equal
//            the serial unit's (the result compared where the flag says there is one).
// The latencies are rtl/pipe_latency.vh's and tb/serial_latency.vh's functions (which units-latency-formulas checks
// against model/timing.c); the handshake's checker is tb/serial_latency_check.v (the unit
// benches' too), the valid bits' tb/formal/pipe_vt_check.sv (toward_props.sv's too).
`default_nettype none

// One operation through a serial unit (done LAT_S after start) and a pipelined one (out
// LAT_P after in): both results are kept, and compared once both are out.
module miter_check #(parameter integer LAT_S = 4, parameter integer LAT_P = 4, parameter integer RW = 8) (
    input wire clk, input wire reset, output wire f_init_o, output wire start,
    input wire done, input wire [RW-1:0] s_res, input wire s_ok,
    input wire out_valid, input wire out_tag, input wire [RW-1:0] p_res, input wire p_ok
);
    localparam integer LAT_MAX = LAT_S > LAT_P ? LAT_S : LAT_P;
    reg f_init = 1'b1;
    reg [1:0] cyc = 2'd0;                            // cycles since the reset cycle, to 3
    always @(posedge clk) begin
        f_init <= 1'b0;
        if (cyc != 2'd3) cyc <= cyc + 2'd1;
    end
    always @* assume (reset == f_init);
    assign f_init_o = f_init;
    assign start = cyc == 2'd2;                      // the one operation
    reg [LAT_MAX:0] pend;
    reg [RW-1:0]    s_q, p_q;
    reg             s_ok_q, p_ok_q;
    always @(posedge clk) begin
        pend <= reset ? {(LAT_MAX + 1){1'b0}} : {pend[LAT_MAX-1:0], start};
        if (done) begin
            s_q    <= s_res;
            s_ok_q <= s_ok;
        end
        if (out_valid && out_tag) begin
            p_q    <= p_res;
            p_ok_q <= p_ok;
        end
    end
    always @* if (!f_init) begin
        if (pend[LAT_S-1]) assert (done);
        if (pend[LAT_P-1]) assert (out_valid && out_tag);
        if (pend[LAT_MAX]) assert (p_ok_q == s_ok_q && (!s_ok_q || p_q == s_q));
        cover (pend[LAT_MAX] && s_ok_q);
    end
endmodule

// ---- spring_force, spring_force_pipe ----

module spring_hs #(
    parameter integer W = 8, parameter integer F = 4, parameter integer SQRT_BITS = 1,
    parameter integer DIV_BITS = 1, parameter integer DIM = 2
) (
    input wire clk, input wire reset, input wire start,
    input wire [DIM*W-1:0] a, input wire [DIM*W-1:0] a_p, input wire [DIM*W-1:0] b, input wire [DIM*W-1:0] b_p,
    input wire [W-1:0] rest_len, input wire [W-1:0] ks, input wire [W-1:0] kd
);
`include "pipe_latency.vh"
`include "serial_latency.vh"
    localparam integer LAT = spring_latency(SQRT_BITS, DIV_BITS, DIM, 1, 0);
    wire busy, done, valid;
    wire [DIM*W-1:0] f;
    spring_force #(.W(W), .F(F), .SQRT_BITS(SQRT_BITS), .DIV_BITS(DIV_BITS), .DIM(DIM)) dut (
        .clk(clk), .reset(reset), .start(start), .pos_a(a), .prev_a(a_p), .pos_b(b), .prev_b(b_p),
        .rest_len(rest_len), .ks(ks), .kd(kd), .busy(busy), .done(done), .f(f), .valid(valid));
    serial_latency_check #(.DEPTH(LAT)) chk (.clk(clk), .reset(reset), .latency(LAT[15:0]), .start(start), .busy(busy),
                                             .done(done), .violations());
    wire unused = &{1'b0, f, valid};
endmodule

module spring_pipe_vt #(
    parameter integer W = 8, parameter integer F = 4, parameter integer SQRT_BITS = 1,
    parameter integer DIV_BITS = 1, parameter integer DIM = 2, parameter integer TAG_W = 3
) (
    input wire clk, input wire reset, input wire in_valid,
    input wire [DIM*W-1:0] in_a, input wire [DIM*W-1:0] in_ap, input wire [DIM*W-1:0] in_b, input wire [DIM*W-1:0] in_bp,
    input wire [W-1:0] in_rest, input wire [W-1:0] in_ks, input wire [W-1:0] in_kd, input wire [TAG_W-1:0] in_tag
);
`include "pipe_latency.vh"
`include "serial_latency.vh"
    localparam integer LAT = spring_pipe_latency(SQRT_BITS, DIV_BITS, 1, 0);
    wire out_valid, out_ok;
    wire [DIM*W-1:0] out_f;
    wire [TAG_W-1:0] out_tag;
    spring_force_pipe #(.W(W), .F(F), .SQRT_BITS(SQRT_BITS), .DIV_BITS(DIV_BITS), .DIM(DIM), .TAG_W(TAG_W)) dut (
        .clk(clk), .reset(reset), .in_valid(in_valid), .in_a(in_a), .in_ap(in_ap), .in_b(in_b), .in_bp(in_bp),
        .in_rest(in_rest), .in_ks(in_ks), .in_kd(in_kd), .in_tag(in_tag),
        .out_valid(out_valid), .out_f(out_f), .out_ok(out_ok), .out_tag(out_tag));
    pipe_vt_check #(.LAT(LAT), .TAG_W(TAG_W)) chk (.clk(clk), .reset(reset), .in_valid(in_valid), .in_tag(in_tag),
        .out_valid(out_valid), .out_tag(out_tag));
    wire unused = &{1'b0, out_f, out_ok};
endmodule

module spring_miter #(
    parameter integer W = 8, parameter integer F = 4, parameter integer SQRT_BITS = 1,
    parameter integer DIV_BITS = 1, parameter integer DIM = 2
) (
    input wire clk, input wire reset, input wire in_valid,
    input wire [DIM*W-1:0] in_a, input wire [DIM*W-1:0] in_ap, input wire [DIM*W-1:0] in_b, input wire [DIM*W-1:0] in_bp,
    input wire [W-1:0] in_rest, input wire [W-1:0] in_ks, input wire [W-1:0] in_kd
);
`include "pipe_latency.vh"
`include "serial_latency.vh"
    localparam integer LAT_S = spring_latency(SQRT_BITS, DIV_BITS, DIM, 1, 0);
    localparam integer LAT_P = spring_pipe_latency(SQRT_BITS, DIV_BITS, 1, 0);
    (* anyconst *) reg [DIM*W-1:0] op_a, op_ap, op_b, op_bp;
    (* anyconst *) reg [W-1:0]     op_rest, op_ks, op_kd;
    wire f_init, start, busy, done, valid, out_valid, out_ok;
    wire [DIM*W-1:0] f, out_f;
    wire [0:0] out_tag;
    spring_force #(.W(W), .F(F), .SQRT_BITS(SQRT_BITS), .DIV_BITS(DIV_BITS), .DIM(DIM)) u_serial (
        .clk(clk), .reset(reset), .start(start), .pos_a(op_a), .prev_a(op_ap), .pos_b(op_b), .prev_b(op_bp),
        .rest_len(op_rest), .ks(op_ks), .kd(op_kd), .busy(busy), .done(done), .f(f), .valid(valid));
    spring_force_pipe #(.W(W), .F(F), .SQRT_BITS(SQRT_BITS), .DIV_BITS(DIV_BITS), .DIM(DIM), .TAG_W(1)) u_pipe (
        .clk(clk), .reset(reset), .in_valid(start ? 1'b1 : in_valid),
        .in_a(start ? op_a : in_a), .in_ap(start ? op_ap : in_ap), .in_b(start ? op_b : in_b), .in_bp(start ? op_bp : in_bp),
        .in_rest(start ? op_rest : in_rest), .in_ks(start ? op_ks : in_ks), .in_kd(start ? op_kd : in_kd),
        .in_tag(start), .out_valid(out_valid), .out_f(out_f), .out_ok(out_ok), .out_tag(out_tag));
    miter_check #(.LAT_S(LAT_S), .LAT_P(LAT_P), .RW(DIM * W)) chk (
        .clk(clk), .reset(reset), .f_init_o(f_init), .start(start), .done(done), .s_res(f), .s_ok(valid),
        .out_valid(out_valid), .out_tag(out_tag), .p_res(out_f), .p_ok(out_ok));
    wire unused = &{1'b0, busy, f_init};
endmodule

// ---- toward_prev, toward_prev_pipe ----

module prev_hs #(
    parameter integer W = 8, parameter integer F = 4, parameter integer SQRT_BITS = 1,
    parameter integer DIV_BITS = 1, parameter integer DIM = 2
) (
    input wire clk, input wire reset, input wire start, input wire excess,
    input wire [DIM*W-1:0] p, input wire [DIM*W-1:0] c, input wire [DIM*W-1:0] pp, input wire [DIM*W-1:0] pc,
    input wire [W-1:0] rest_len
);
`include "pipe_latency.vh"
`include "serial_latency.vh"
    localparam integer LAT = toward_latency(SQRT_BITS, DIV_BITS, DIM, 1, 0, 1);
    wire busy, done, valid;
    wire [DIM*W-1:0] t;
    toward_prev #(.W(W), .F(F), .SQRT_BITS(SQRT_BITS), .DIV_BITS(DIV_BITS), .DIM(DIM)) dut (
        .clk(clk), .reset(reset), .start(start), .excess(excess), .p(p), .c(c), .pp(pp), .pc(pc),
        .rest_len(rest_len), .busy(busy), .done(done), .t(t), .valid(valid));
    serial_latency_check #(.DEPTH(LAT)) chk (.clk(clk), .reset(reset), .latency(LAT[15:0]), .start(start), .busy(busy),
                                             .done(done), .violations());
    wire unused = &{1'b0, t, valid};
endmodule

module prev_pipe_vt #(
    parameter integer W = 8, parameter integer F = 4, parameter integer SQRT_BITS = 1,
    parameter integer DIV_BITS = 1, parameter integer DIM = 2, parameter integer TAG_W = 3,
    parameter [0:0] CARRY = 1'b0
) (
    input wire clk, input wire reset, input wire in_valid, input wire in_excess,
    input wire [DIM*W-1:0] in_p, input wire [DIM*W-1:0] in_c, input wire [DIM*W-1:0] in_pp, input wire [DIM*W-1:0] in_pc,
    input wire [W-1:0] in_rest, input wire [TAG_W-1:0] in_tag
);
`include "pipe_latency.vh"
`include "serial_latency.vh"
    localparam integer LAT = toward_prev_pipe_latency(SQRT_BITS, DIV_BITS, 1, 0);
    wire out_valid, out_ok;
    wire [DIM*W-1:0] out_t, out_p, out_c;
    wire [TAG_W-1:0] out_tag;
    toward_prev_pipe #(.W(W), .F(F), .SQRT_BITS(SQRT_BITS), .DIV_BITS(DIV_BITS), .DIM(DIM), .TAG_W(TAG_W),
                       .CARRY(CARRY)) dut (
        .clk(clk), .reset(reset), .in_valid(in_valid), .in_excess(in_excess), .in_p(in_p), .in_c(in_c),
        .in_pp(in_pp), .in_pc(in_pc), .in_rest(in_rest), .in_tag(in_tag), .out_valid(out_valid),
        .out_t(out_t), .out_ok(out_ok), .out_tag(out_tag), .out_p(out_p), .out_c(out_c));
    pipe_vt_check #(.LAT(LAT), .TAG_W(TAG_W)) chk (.clk(clk), .reset(reset), .in_valid(in_valid), .in_tag(in_tag),
        .out_valid(out_valid), .out_tag(out_tag));
    wire unused = &{1'b0, out_t, out_ok, out_p, out_c};
endmodule

module prev_miter #(
    parameter integer W = 8, parameter integer F = 4, parameter integer SQRT_BITS = 1,
    parameter integer DIV_BITS = 1, parameter integer DIM = 2
) (
    input wire clk, input wire reset, input wire in_valid, input wire in_excess,
    input wire [DIM*W-1:0] in_p, input wire [DIM*W-1:0] in_c, input wire [DIM*W-1:0] in_pp, input wire [DIM*W-1:0] in_pc,
    input wire [W-1:0] in_rest
);
`include "pipe_latency.vh"
`include "serial_latency.vh"
    localparam integer LAT_S = toward_latency(SQRT_BITS, DIV_BITS, DIM, 1, 0, 1);
    localparam integer LAT_P = toward_prev_pipe_latency(SQRT_BITS, DIV_BITS, 1, 0);
    (* anyconst *) reg [DIM*W-1:0] op_p, op_c, op_pp, op_pc;
    (* anyconst *) reg [W-1:0]     op_rest;
    (* anyconst *) reg             op_excess;
    wire f_init, start, busy, done, valid, out_valid, out_ok;
    wire [DIM*W-1:0] t, out_t, out_p, out_c;
    wire [0:0] out_tag;
    toward_prev #(.W(W), .F(F), .SQRT_BITS(SQRT_BITS), .DIV_BITS(DIV_BITS), .DIM(DIM)) u_serial (
        .clk(clk), .reset(reset), .start(start), .excess(op_excess), .p(op_p), .c(op_c), .pp(op_pp), .pc(op_pc),
        .rest_len(op_rest), .busy(busy), .done(done), .t(t), .valid(valid));
    toward_prev_pipe #(.W(W), .F(F), .SQRT_BITS(SQRT_BITS), .DIV_BITS(DIV_BITS), .DIM(DIM), .TAG_W(1)) u_pipe (
        .clk(clk), .reset(reset), .in_valid(start ? 1'b1 : in_valid), .in_excess(start ? op_excess : in_excess),
        .in_p(start ? op_p : in_p), .in_c(start ? op_c : in_c), .in_pp(start ? op_pp : in_pp),
        .in_pc(start ? op_pc : in_pc), .in_rest(start ? op_rest : in_rest), .in_tag(start),
        .out_valid(out_valid), .out_t(out_t), .out_ok(out_ok), .out_tag(out_tag), .out_p(out_p), .out_c(out_c));
    miter_check #(.LAT_S(LAT_S), .LAT_P(LAT_P), .RW(DIM * W)) chk (
        .clk(clk), .reset(reset), .f_init_o(f_init), .start(start), .done(done), .s_res(t), .s_ok(valid),
        .out_valid(out_valid), .out_tag(out_tag), .p_res(out_t), .p_ok(out_ok));
    wire unused = &{1'b0, busy, f_init, out_p, out_c};
endmodule

`resetall
