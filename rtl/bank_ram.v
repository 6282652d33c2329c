`default_nettype none
`timescale 1ns / 1ps

`include "strand_defs.vh"

/*
 * bank_ram - a node memory: one strand_ram, or (BANKS = 2) two, the even nodes in one
 * bank and the odd nodes in the other, so that two neighbouring nodes can be read,
 * and two written, in the same cycle.
 *
 * Node i lives in bank i mod 2 at row i / 2. Every port keeps strand_ram's timing:
 * synchronous reads (address now, data the cycle after, read before write), a read
 * port whose enable is low holds its output, nothing is reset.
 *
 *   write port 1 (we, waddr, wdata): any node.
 *   write port 2 (we2, waddr2, wdata2; BANKS = 2): a node of the other bank than
 *                port 1's write in the same cycle (the caller guarantees it: two
 *                writes to one bank in one cycle are not supported, and a simulation
 *                check stops on one). A bank's address and data follow port 2 when
 *                port 2 writes it, else port 1: port 2's enable comes from registered
 *                pass flags, port 1's through the writer select (init walk, loads, the
 *                sequencer), so choosing by port 2 keeps that select off the data path.
 *   read port A (re_a, raddr_a): one node, its word on rdata_a; with BANKS = 2 both
 *                banks read the row raddr_a / 2 and rdata_a is the one of bank
 *                raddr_a mod 2 (a registered select after the two outputs).
 *   pair read   (pair_re, prow_e, prow_o; BANKS = 2): instead of port A, the even
 *                bank reads row prow_e and the odd bank row prow_o; the words come
 *                out on rdata_e and rdata_o (the banks' own outputs, which also
 *                carry a port-A read's two rows).
 *   read port B (re_b, raddr_b; READ_B): one node, as port A; with B_REG, its word
 *                is registered once more, as each bank gives it (rdata_b two cycles
 *                after raddr_b, the bank select after that register): a block RAM's
 *                output without its output register is slow (about 5.8 ns on an ECP5)
 *                and then reaches only a flip-flop beside it.
 *
 * With BANKS = 1 it is one strand_ram and the pair and second-write ports are unused
 * (rdata_e carries port A's word, rdata_o is 0).
 *
 * NO_COLLIDE_A: the word port A or the pair read gives when its row was written in the
 * same cycle is never used (strand_ram: a simulation gives a poisoned word then, which
 * lockstep would catch if it were used).
 *
 * Latency: 1 cycle per read (port B with B_REG: 2); throughput: BANKS writes and BANKS port-A reads a cycle
 * (one a bank), and one port-B read.
 */
module bank_ram #(
    parameter integer WIDTH     = 32, // bits per word
    parameter integer DEPTH     = 16, // words (nodes)
    parameter integer ABITS     = 4,  // node address bits, 2^ABITS >= DEPTH
    parameter integer BLOCK_MIN = 64, // strand_ram's block RAM threshold (per bank)
    parameter [0:0]   READ_B    = 1'b1, // 0: no port B (rdata_b is 0)
    parameter integer BANKS     = 1,  // 1: one memory; 2: even and odd banks
    parameter [0:0]   B_REG     = 1'b0, // 1: port B's word registered once more (latency 2)
    // 1: a word port A or the pair read gives in the cycle its row is written is never used
    // (strand_ram NO_COLLIDE_A: its block RAMs go without collision logic)
    parameter [0:0]   NO_COLLIDE_A = 1'b0
) (
    input  wire             clk,
    input  wire             reset,    // only for the simulation check below (the memory is not reset)
    input  wire             we,
    input  wire [ABITS-1:0] waddr,
    input  wire [WIDTH-1:0] wdata,
    input  wire             we2,
    input  wire [ABITS-1:0] waddr2,
    input  wire [WIDTH-1:0] wdata2,
    input  wire             re_a,
    input  wire [ABITS-1:0] raddr_a,
    output wire [WIDTH-1:0] rdata_a,
    input  wire             pair_re,
    input  wire [ABITS-1:0] prow_e,   // rows (node / 2), ABITS wide for simplicity
    input  wire [ABITS-1:0] prow_o,
    output wire [WIDTH-1:0] rdata_e,
    output wire [WIDTH-1:0] rdata_o,
    input  wire             re_b,
    input  wire [ABITS-1:0] raddr_b,
    output wire [WIDTH-1:0] rdata_b
);

    `STRAND_CHECK(bank_ram_BANKS, BANKS == 1 || BANKS == 2, ("bank_ram: BANKS must be 1 or 2 (BANKS=%0d) in %m", BANKS))

    generate
        if (BANKS == 1) begin : g_one
            wire [WIDTH-1:0] q_b;
            strand_ram #(.WIDTH(WIDTH), .DEPTH(DEPTH), .ABITS(ABITS), .BLOCK_MIN(BLOCK_MIN), .READ_B(READ_B), .NO_COLLIDE_A(NO_COLLIDE_A)) u_ram (
                .clk(clk), .we(we), .waddr(waddr), .wdata(wdata),
                .re_a(re_a), .raddr_a(raddr_a), .rdata_a(rdata_a),
                .re_b(re_b), .raddr_b(raddr_b), .rdata_b(q_b));
            if (B_REG) begin : g_b_reg
                reg [WIDTH-1:0] q_b_r;
                always @(posedge clk) q_b_r <= q_b;
                assign rdata_b = q_b_r;
            end else begin : g_b_now
                assign rdata_b = q_b;
            end
            assign rdata_e = rdata_a;
            assign rdata_o = {WIDTH{1'b0}};
            wire unused_pair = &{1'b0, reset, we2, waddr2, wdata2, pair_re, prow_e, prow_o};
        end else begin : g_two
            // a bank's rows: ceil(DEPTH / 2), addressed by the node address without its bit 0
            localparam integer BDEPTH = (DEPTH + 1) / 2;
            localparam integer RW     = ABITS > 1 ? ABITS - 1 : 1;
            /* verilator lint_off UNUSEDSIGNAL */
            // a row is the address without bit 0: the shifted-in top bit is never read
            wire [ABITS-1:0] w1_row = waddr >> 1, w2_row = waddr2 >> 1, a_row = raddr_a >> 1, b_row = raddr_b >> 1;
            wire [ABITS-1:0] pe_row = prow_e, po_row = prow_o;
            /* verilator lint_on UNUSEDSIGNAL */
            wire [WIDTH-1:0] q_a [0:1];
            wire [WIDTH-1:0] q_b [0:1];
            genvar b;
            for (b = 0; b < 2; b = b + 1) begin : g_bank
                localparam [0:0] B = b;
                wire          w1   = we && waddr[0] == B;   // port 1 writes this bank
                wire          w2   = we2 && waddr2[0] == B; // port 2 writes this bank
                wire [RW-1:0] prow = b == 0 ? pe_row[RW-1:0] : po_row[RW-1:0];
                strand_ram #(.WIDTH(WIDTH), .DEPTH(BDEPTH), .ABITS(RW), .BLOCK_MIN(BLOCK_MIN), .READ_B(READ_B),
                             .NO_COLLIDE_A(NO_COLLIDE_A)) u_ram (
                    .clk(clk), .we(w1 || w2), .waddr(w2 ? w2_row[RW-1:0] : w1_row[RW-1:0]), .wdata(w2 ? wdata2 : wdata),
                    .re_a(re_a || pair_re), .raddr_a(pair_re ? prow : a_row[RW-1:0]), .rdata_a(q_a[b]),
                    .re_b(re_b), .raddr_b(b_row[RW-1:0]), .rdata_b(q_b[b]));
`ifndef SYNTHESIS
                // not under reset: the enables come from registers that reset clears, and
                // before its first edge they hold whatever the simulator started them with
                always @(posedge clk)
                    if (!reset && w1 && w2) begin
                        $display("bank_ram: both write ports write bank %0d in one cycle in %m", b);
                        $fatal(1);
                    end
`endif
            end
            // which bank port A and port B read (held with their outputs)
            reg sel_a, sel_b;
            always @(posedge clk) begin
                if (re_a && !pair_re) sel_a <= raddr_a[0];
                if (re_b) sel_b <= raddr_b[0];
            end
            assign rdata_a = sel_a ? q_a[1] : q_a[0];
            if (B_REG) begin : g_b_reg
                reg [WIDTH-1:0] q_b_r [0:1];
                reg             sel_b_r;
                always @(posedge clk) begin
                    q_b_r[0] <= q_b[0];
                    q_b_r[1] <= q_b[1];
                    sel_b_r  <= sel_b;
                end
                assign rdata_b = sel_b_r ? q_b_r[1] : q_b_r[0];
            end else begin : g_b_now
                assign rdata_b = sel_b ? q_b[1] : q_b[0];
            end
            assign rdata_e = q_a[0];
            assign rdata_o = q_a[1];
        end
    endgenerate

endmodule

`resetall
