`default_nettype none
`timescale 1ns / 1ps

`include "strand_defs.vh"

/*
 * grab_scan - the grab form of the mouse (EN_MOUSE and GRAB): which node is held.
 *
 * At a frame's start (phase GRAB) the scan reads every node through the units'
 * port A in {unit, node} order, one a cycle: cycle i of the phase (i = 0 .. N)
 * addresses node i and judges node i - 1, whose data arrive now, as
 * model/engine_body.h grab_update() does: in_box the box on every axis
 * (|pointer - node| < box), not pinned, and nearer than the best so far in the L1
 * distance (a saturating sum, x + y [+ z]); ties keep the first. At the scan's end
 * (scan_end, cycle N) the button decides: up lets go; pressed with nothing held,
 * the nearest node found is taken; pressed with a node held, it stays held.
 *
 * held / held_addr are the values after this cycle's edge (the Verlet pass reads
 * node 0 at the very edge that ends the scan, so the units see the new holder in
 * that cycle already). Every |difference| saturates (|min| is max), as fx_abs.
 */
module grab_scan #(
`include "strand_params.vh"
) (
    input  wire             clk,
    input  wire             reset,
    input  wire             frame_start, // a frame starts (the scan follows)
    input  wire             scanning,    // phase GRAB
    input  wire [DIM*W-1:0] mouse,       // the pointer and the button, sampled at the frame start
    input  wire             mouse_down,
    input  wire [DIM*W-1:0] box,
    output wire [AW-1:0]    scan_addr,   // the node the scan reads now
    input  wire [DIM*W-1:0] rd_pos,      // port A data: the node read the cycle before
    input  wire             rd_pinned,
    output wire             scan_end,    // the last cycle of phase GRAB
    output wire             held,        // a node is held (after this cycle)
    output wire [AW-1:0]    held_addr    //   this one
);

`include "strand_addr.vh"

    localparam integer  N = M * K;
    localparam [CW-1:0] N_COUNT = N[CW-1:0];

    reg [CW-1:0] scan_i;      // nodes addressed so far
    reg [AW-1:0] scan_a;      // node scan_i's address
    reg [AW-1:0] data_a;      // the address whose data arrive (node scan_i - 1)
    reg          found_q, held_q;
    reg [W-1:0]  best;
    reg [AW-1:0] cand, held_a;

    // ---- the distance of the node whose data arrive ----
    wire [DIM-1:0]   in_box;   // |pointer - node| < box, per axis
    wire [DIM*W-1:0] dist_ax;     // |pointer - node|, per axis
    wire [DIM*W-1:0] l1_sum;   // the L1 distance, summed lane by lane (x, x + y, x + y + z)
    genvar k;
    generate
        for (k = 0; k < DIM; k = k + 1) begin : g_lane
            wire [W-1:0] dd, nd;
            /* verilator lint_off PINCONNECTEMPTY */
            // saturation flags are not needed: the saturated value is the result
            fx_add #(.W(W), .SUB(1)) u_dd (.sub(1'b1), .a(mouse[k*W +: W]), .b(rd_pos[k*W +: W]), .y(dd), .sat());
            fx_add #(.W(W), .SUB(1)) u_nd (.sub(1'b1), .a({W{1'b0}}), .b(dd), .y(nd), .sat());  // |min| is max
            assign dist_ax[k*W +: W] = dd[W-1] ? nd : dd;
            assign in_box[k] = $signed(dist_ax[k*W +: W]) < $signed(box[k*W +: W]);
            if (k == 0) begin : g_first
                assign l1_sum[W-1:0] = dist_ax[W-1:0];
            end else begin : g_sum
                fx_add #(.W(W), .SUB(0)) u_sum (.sub(1'b0), .a(l1_sum[(k-1)*W +: W]), .b(dist_ax[k*W +: W]), .y(l1_sum[k*W +: W]), .sat());
            end
            /* verilator lint_on PINCONNECTEMPTY */
        end
    endgenerate
    wire [W-1:0] l1 = l1_sum[(DIM-1)*W +: W];

    wire          take      = scan_i != {CW{1'b0}} && &in_box && !rd_pinned && (!found_q || $signed(l1) < $signed(best));
    wire          found_n   = found_q || take;
    wire [AW-1:0] cand_n    = take ? data_a : cand;
    assign scan_end  = scanning && scan_i == N_COUNT;
    assign held      = scan_end ? mouse_down && (held_q || found_n) : held_q;
    assign held_addr = scan_end && mouse_down && !held_q && found_n ? cand_n : held_a;
    assign scan_addr = scan_a;

    always @(posedge clk) begin
        if (reset) begin
            scan_i  <= {CW{1'b0}};
            scan_a  <= {AW{1'b0}};
            data_a  <= {AW{1'b0}};
            found_q <= 1'b0;
            best    <= {W{1'b0}};
            cand    <= {AW{1'b0}};
            held_q  <= 1'b0;
            held_a  <= {AW{1'b0}};
        end else if (frame_start) begin
            scan_i  <= {CW{1'b0}};
            scan_a  <= {AW{1'b0}};
            found_q <= 1'b0;
        end else if (scanning) begin
            data_a  <= scan_a;
            found_q <= found_n;
            cand    <= cand_n;
            if (take) best <= l1;
            held_q  <= held;
            held_a  <= held_addr;
            if (!scan_end) begin
                scan_i <= scan_i + 1'b1;
                scan_a <= next_node(scan_a);
            end
        end
    end

endmodule

`resetall
