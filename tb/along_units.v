`default_nettype none
`timescale 1ns / 1ps

/*
 * along_units - eight copies of rtl/fx_along_pipe.v side by side, each with its own W, MB
 * and DIM (the parameters W0..W7, MB0..MB7, DIM0..DIM7), for the Verilator test
 * tb/along_units.cpp: one build checks every configuration. Not synthesized.
 *
 * Slot i takes d from d_all[i*96 +: DIMi*Wi] (lane k at k*Wi), rest from rest_all[i*32 +: Wi]
 * and gives t in t_all[i*96 +: DIMi*Wi], ok in ok_all[i]; unused bits are zero.
 */
module along_units #(
    parameter integer W0 = 8,  parameter integer MB0 = 6,  parameter integer DIM0 = 2,
    parameter integer W1 = 8,  parameter integer MB1 = 8,  parameter integer DIM1 = 3,
    parameter integer W2 = 18, parameter integer MB2 = 17, parameter integer DIM2 = 2,
    parameter integer W3 = 32, parameter integer MB3 = 17, parameter integer DIM3 = 2,
    parameter integer W4 = 32, parameter integer MB4 = 17, parameter integer DIM4 = 3,
    parameter integer W5 = 32, parameter integer MB5 = 8,  parameter integer DIM5 = 3,
    parameter integer W6 = 32, parameter integer MB6 = 20, parameter integer DIM6 = 3,
    parameter integer W7 = 12, parameter integer MB7 = 11, parameter integer DIM7 = 3
) (
    input  wire          clk,
    input  wire          reset,
    input  wire [767:0]  d_all,
    input  wire [255:0]  rest_all,
    output wire [767:0]  t_all,
    output wire [7:0]    ok_all
);
    function integer pick(input integer i, input integer a0, input integer a1, input integer a2, input integer a3,
                          input integer a4, input integer a5, input integer a6, input integer a7);
        pick = i == 0 ? a0 : i == 1 ? a1 : i == 2 ? a2 : i == 3 ? a3 : i == 4 ? a4 : i == 5 ? a5 : i == 6 ? a6 : a7;
    endfunction
    genvar i;
    generate
        for (i = 0; i < 8; i = i + 1) begin : g_slot
            localparam integer W   = pick(i, W0, W1, W2, W3, W4, W5, W6, W7);
            localparam integer MB  = pick(i, MB0, MB1, MB2, MB3, MB4, MB5, MB6, MB7);
            localparam integer DIM = pick(i, DIM0, DIM1, DIM2, DIM3, DIM4, DIM5, DIM6, DIM7);
            fx_along_pipe #(.W(W), .MB(MB), .DIM(DIM)) u_along (
                .clk(clk), .reset(reset), .d(d_all[i*96 +: DIM*W]), .rest(rest_all[i*32 +: W]),
                .t(t_all[i*96 +: DIM*W]), .ok(ok_all[i]));
            if (DIM * W < 96) begin : g_pad
                assign t_all[i*96 + DIM*W +: 96 - DIM*W] = {(96 - DIM*W){1'b0}};
            end
            /* verilator lint_off UNUSEDSIGNAL */
            // the slot's unused input bits
            wire unused = &{1'b0, d_all[i*96 +: 96], rest_all[i*32 +: 32]};
            /* verilator lint_on UNUSEDSIGNAL */
        end
    endgenerate
endmodule

`resetall
