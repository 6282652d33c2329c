`default_nettype none
`timescale 1ns / 1ps

`include "strand_defs.vh"

/*
 * delay_line - a word delayed by a fixed number of cycles: out in cycle t is what
 * in was in cycle t - DELAY.
 *
 * A pipeline carries the operands it needs again at its end (a datapath's P and d
 * beside its root and divider) in one of these rather than in a register per stage:
 * a ring of DELAY - 2 words in a strand_ram, written every cycle at `slot` and read
 * at the same address (read before write), so the word read is the one written
 * DELAY - 2 cycles earlier; the RAM's read register and an output register add the
 * last two cycles (the output register keeps a block RAM's slow clock-to-output off
 * the paths that use the word). The ring goes to LUT RAM or block RAM (strand_ram's
 * BLOCK_MIN rule) instead of DELAY x WIDTH flip-flops. A DELAY of 1 or 2 is a
 * register chain.
 *
 * Nothing is reset but the slot counter: the words are undefined for the first DELAY
 * cycles after reset; the pipeline's own valid bits say when a word means something.
 */
module delay_line #(
    parameter integer WIDTH     = 32,
    parameter integer DELAY     = 8,  // cycles, >= 1
    parameter integer BLOCK_MIN = 64  // strand_ram: ring depth from which block RAM is asked for
) (
    input  wire             clk,
    input  wire             reset,    // synchronous: the slot counter
    input  wire [WIDTH-1:0] in,
    output wire [WIDTH-1:0] out
);

    `STRAND_CHECK(delay_line_DELAY, DELAY >= 1, ("delay_line: DELAY must be >= 1 (DELAY=%0d) in %m", DELAY))

    generate
        if (DELAY <= 2) begin : g_regs
            reg [WIDTH-1:0] r [0:DELAY-1];
            integer i;
            always @(posedge clk) begin
                r[0] <= in;
                for (i = 1; i < DELAY; i = i + 1) r[i] <= r[i-1];
            end
            assign out = r[DELAY-1];
            wire unused_reset = &{1'b0, reset};
        end else begin : g_ring
            localparam integer RING  = DELAY - 2;
            localparam integer SBITS = RING > 1 ? $clog2(RING) : 1;
            localparam integer LAST_I = RING - 1;
            localparam [SBITS-1:0] LAST = LAST_I[SBITS-1:0];
            reg [SBITS-1:0] slot;
            always @(posedge clk)
                if (reset || slot == LAST) slot <= {SBITS{1'b0}};
                else slot <= slot + 1'b1;
            wire [WIDTH-1:0] word;
            reg  [WIDTH-1:0] out_q;
            /* verilator lint_off PINCONNECTEMPTY */
            // one read port (READ_B = 0)
            strand_ram #(.WIDTH(WIDTH), .DEPTH(RING), .ABITS(SBITS), .BLOCK_MIN(BLOCK_MIN), .READ_B(1'b0)) u_ring (
                .clk(clk), .we(1'b1), .waddr(slot), .wdata(in),
                .re_a(1'b1), .raddr_a(slot), .rdata_a(word),
                .re_b(1'b0), .raddr_b(slot), .rdata_b());
            /* verilator lint_on PINCONNECTEMPTY */
            always @(posedge clk) out_q <= word;
            assign out = out_q;
        end
    endgenerate

endmodule

`resetall
