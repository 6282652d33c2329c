`default_nettype none
`timescale 1ns / 1ps

`include "strand_defs.vh"

/*
 * strand_ram - node and edge storage: a reset-free synchronous memory with one
 * write port and two read ports.
 *
 * DEPTH words of WIDTH bits. A write (we) stores wdata at waddr at the clock edge;
 * a read port with its enable high loads the word at its address into its output
 * register at the same edge (data the cycle after the address), reading the old
 * word when it is the one being written (read before write); with the enable low
 * the output holds. Nothing is reset: the contents are undefined until written
 * (the init walk, NODE and EDGE writes fill them), which is what lets FPGA flows
 * map the memory to block RAM.
 *
 * Where it goes: a memory of DEPTH >= BLOCK_MIN words asks for block RAM
 * (ram_style "block": SB_RAM40_4K on iCE40, DP16KD on ECP5, RAMB18 on 7-series);
 * a smaller one asks for nothing, and Yosys picks by cost: LUT RAM on ECP5 and
 * Xilinx, flip-flops on iCE40 (which has no LUT RAM). A second read port (READ_B) makes Yosys store
 * the memory twice, each copy with one read port. An address at or past DEPTH must
 * not be written; a read there gives an undefined word. NO_COLLIDE_A: the caller never
 * uses a word port A reads in the cycle it is written (the read-before-write above is
 * then never asked of port A, and its block RAM is mapped without the logic that would
 * provide it; a simulation poisons that word).
 *
 * Latency: 1 cycle per read; throughput one write and two reads per cycle.
 */
module strand_ram #(
    parameter integer WIDTH     = 32, // bits per word
    parameter integer DEPTH     = 16, // words
    parameter integer ABITS     = 4,  // address bits, 2^ABITS >= DEPTH
    parameter integer BLOCK_MIN = 64, // DEPTH at or above which block RAM is asked for
    parameter [0:0]   READ_B    = 1'b1, // 0: no port B (rdata_b is 0)
    // 1: the caller never uses the word port A reads in the cycle it is written, so port
    // A's block RAM may give anything then, and Yosys leaves out the logic that would give
    // the old word (a bypass after the RAM's output: on ECP5 a LUT and a long route between
    // the DP16KD and its reader, after its slow clock-to-output). A simulation gives the
    // old word inverted then: lockstep with the C model catches it if it is ever used.
    parameter [0:0]   NO_COLLIDE_A = 1'b0
) (
    input  wire             clk,
    input  wire             we,
    input  wire [ABITS-1:0] waddr,
    input  wire [WIDTH-1:0] wdata,
    input  wire             re_a,
    input  wire [ABITS-1:0] raddr_a,
    output reg  [WIDTH-1:0] rdata_a,
    input  wire             re_b,
    input  wire [ABITS-1:0] raddr_b,
    output reg  [WIDTH-1:0] rdata_b
);

    `STRAND_CHECK(strand_ram_ABITS_too_narrow, (1 << ABITS) >= DEPTH && DEPTH >= 1,
                  ("strand_ram: ABITS=%0d cannot address DEPTH=%0d words in %m", ABITS, DEPTH))

    // the storage: one array, its style by size; the read ports below read it
    wire [WIDTH-1:0] word_a, word_b;
    generate
        if (DEPTH >= BLOCK_MIN && NO_COLLIDE_A) begin : g_block_free
            // port A's copy without the read-before-write guarantee; port B keeps its own
            // (Yosys stores a memory once per read port anyway; no read, no copy)
            (* ram_style = "block", no_rw_check *) reg [WIDTH-1:0] mem_a [0:DEPTH-1];
            (* ram_style = "block" *) reg [WIDTH-1:0] mem_b [0:DEPTH-1];
            always @(posedge clk) if (we) begin
                mem_a[waddr] <= wdata;
                mem_b[waddr] <= wdata;
            end
            assign word_a = mem_a[raddr_a];
            assign word_b = mem_b[raddr_b];
        end else if (DEPTH >= BLOCK_MIN) begin : g_block
            (* ram_style = "block" *) reg [WIDTH-1:0] mem [0:DEPTH-1];
            always @(posedge clk) if (we) mem[waddr] <= wdata;
            assign word_a = mem[raddr_a];
            assign word_b = mem[raddr_b];
        end else begin : g_small
            reg [WIDTH-1:0] mem [0:DEPTH-1];  // no request: the tool picks by cost
            always @(posedge clk) if (we) mem[waddr] <= wdata;
            assign word_a = mem[raddr_a];
            assign word_b = mem[raddr_b];
        end
    endgenerate
`ifdef SYNTHESIS
    always @(posedge clk) if (re_a) rdata_a <= word_a;
`else
    wire collide_a = NO_COLLIDE_A && we && raddr_a == waddr;  // the word is undefined: poison it
    always @(posedge clk) if (re_a) rdata_a <= collide_a ? ~word_a : word_a;
`endif
    generate
        if (READ_B) begin : g_port_b
            always @(posedge clk) if (re_b) rdata_b <= word_b;
        end else begin : g_no_port_b
            always @(posedge clk) rdata_b <= {WIDTH{1'b0}};  // a constant: synthesis removes it
            wire unused_b = &{1'b0, re_b, raddr_b, word_b};
        end
    endgenerate

endmodule

`resetall
