// pipe_vt_check - a pipelined unit's out_valid and out_tag are its in_valid and in_tag LAT
// cycles earlier (since reset: one operation a clock, none dropped, none repeated), and
// out_valid is low after a reset. The valid-bit contract of toward_pipe, toward_prev_pipe
// and spring_force_pipe (tb/formal/toward_props.sv, datapath_props.sv), their LAT from
// rtl/pipe_latency.vh.
`default_nettype none

module pipe_vt_check #(parameter integer LAT = 4, parameter integer TAG_W = 3) (
    input wire clk, input wire reset, input wire in_valid, input wire [TAG_W-1:0] in_tag,
    input wire out_valid, input wire [TAG_W-1:0] out_tag
);
    reg f_init = 1'b1;
    always @(posedge clk) f_init <= 1'b0;
    always @* if (f_init) assume (reset);
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
endmodule

`resetall
