`default_nettype none
`timescale 1ns / 1ps

`include "strand_regs.vh"
`include "params.vh"

/*
 * sim_top - strand_top built for one scene: its parameters come from the params.vh
 * that 'strand hwgen SCENE DIR' writes, so the Verilator harness builds exactly the
 * effects the scene names. Ports as strand_top.
 */
module sim_top #(
    parameter integer W  = `STRAND_W,
    parameter integer M  = `STRAND_M,
    parameter integer K  = `STRAND_K,
    parameter integer UW = M > 1 ? $clog2(M) : 1,
    parameter integer IW = K > 1 ? $clog2(K) : 1,
    parameter integer NE = M * K > `STRAND_E_RODS ? (M * K > `STRAND_E_SPRINGS ? M * K : `STRAND_E_SPRINGS)
                                                  : (`STRAND_E_RODS > `STRAND_E_SPRINGS ? `STRAND_E_RODS : `STRAND_E_SPRINGS),
    parameter integer CW = $clog2(NE + 1)  // as strand_top derives it
) (
    input  wire            clk,
    input  wire            reset,
    input  wire [W-1:0]    mouse_x,
    input  wire [W-1:0]    mouse_y,
    input  wire [W-1:0]    mouse_z,
    input  wire            mouse_down,
    input  wire            step,
    output wire            frame_done,
    input  wire            cfg_we,
    input  wire [`STRAND_REG_ADDR_BITS-1:0] cfg_addr,
    input  wire [W-1:0]    cfg_data,
    input  wire [UW+IW-1:0] rd_addr,
    output wire [W-1:0]    rd_x,
    output wire [W-1:0]    rd_y,
    output wire [W-1:0]    rd_z,
    output wire [2:0]      phase,
    output wire            fv,
    output wire            fec,
    output wire [UW-1:0]   uidx,
    output wire [IW-1:0]   nidx,
    output wire [CW-1:0]   counter,
    output wire [M-1:0]    wb_valid,
    output wire [M*IW-1:0] wb_idx,
    output wire [M*W-1:0]  wb_x,
    output wire [M*W-1:0]  wb_y,
    output wire [M*W-1:0]  wb_z
);
    strand_top #(
        .W(W), .F(`STRAND_F), .M(M), .K(K), .SQRT_BITS(`STRAND_SQRT_BITS), .DIV_BITS(`STRAND_DIV_BITS),
        .ITER(`STRAND_ITER), .SUBSTEPS(`STRAND_SUBSTEPS), .EN_GRAVITY(`STRAND_EN_GRAVITY),
        .EN_DAMPING(`STRAND_EN_DAMPING), .EN_MOUSE(`STRAND_EN_MOUSE), .EN_CONSTRAINTS(`STRAND_EN_CONSTRAINTS), .RULE(`STRAND_RULE),
        .EN_SPRINGS(`STRAND_EN_SPRINGS), .EN_GROUND(`STRAND_EN_GROUND),
        .GROUND_AXIS(`STRAND_GROUND_AXIS), .GROUND_ABOVE(`STRAND_GROUND_ABOVE),
        .DIM(`STRAND_DIM), .GRAPH(`STRAND_GRAPH), .E_RODS(`STRAND_E_RODS), .E_SPRINGS(`STRAND_E_SPRINGS),
        .GRAB(`STRAND_GRAB)
    ) u_top (
        .clk(clk), .reset(reset), .mouse_x(mouse_x), .mouse_y(mouse_y), .mouse_z(mouse_z), .mouse_down(mouse_down),
        .step(step), .frame_done(frame_done), .cfg_we(cfg_we), .cfg_addr(cfg_addr), .cfg_data(cfg_data),
        .rd_addr(rd_addr), .rd_x(rd_x), .rd_y(rd_y), .rd_z(rd_z), .phase(phase), .fv(fv), .fec(fec),
        .uidx(uidx), .nidx(nidx), .counter(counter),
        .wb_valid(wb_valid), .wb_idx(wb_idx), .wb_x(wb_x), .wb_y(wb_y), .wb_z(wb_z));
endmodule

`resetall
