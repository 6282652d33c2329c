// reset_props - after a reset, strand_core's outputs are defined: two copies of the core
// start from arbitrary (different) states, memories included, see the same reset and then
// the same inputs (register writes, CMD, steps, reads, the mouse), and every output -
// busy, frame_done, irq, the node read port and, with DEBUG = 1, the observation port
// (phase, FV, FEC, the walk's indices and counter, the write-back lanes) - is equal in
// the two in every cycle from the one after the reset on; and in that first cycle the
// phase is IDLE, busy, frame_done and irq are low and a node reads 0. (The observation
// port's write-back lane data are compared when the lane's valid bit says they mean
// something.) So nothing a caller
// or the cycle model can see depends on the state before the reset, and the FSMs behind
// the phase and the walk start from their reset states. Run by tb/formal/reset.sby.
`default_nettype none

`include "strand_regs.vh"

module reset_props #(
    parameter integer W = 8, parameter integer F = 4, parameter integer M = 1, parameter integer K = 2,
    parameter [0:0] RULE = 1'b0, parameter [0:0] ARCH = 1'b0, parameter [0:0] EN_SPRINGS = 1'b0
) (
    input wire clk, input wire reset, input wire cfg_we, input wire [`STRAND_REG_ADDR_BITS-1:0] cfg_addr,
    input wire [W-1:0] cfg_data, input wire step, input wire [W-1:0] mouse_x, input wire [W-1:0] mouse_y,
    input wire mouse_down, input wire [(M > 1 ? $clog2(M) : 1) + (K > 1 ? $clog2(K) : 1) - 1:0] rd_addr
);
    localparam integer UW = M > 1 ? $clog2(M) : 1;
    localparam integer IW = K > 1 ? $clog2(K) : 1;
    localparam integer CW = $clog2(M * K + 1);
    localparam integer DBG_W = 3 + 2 + UW + IW + CW + M * (1 + IW + 3 * W);
    localparam integer LV    = 3 + 2 + UW + IW + CW;     // the write-back lanes' valid bits
    localparam integer CTL_W = LV + M + M * IW;          // everything before the lanes' data
    integer u;

    wire busy0, busy1, fd0, fd1, irq0, irq1;
    wire [W-1:0] x0, y0, z0, x1, y1, z1;
    wire [DBG_W-1:0] dbg0, dbg1;
    strand_core #(.W(W), .F(F), .M(M), .K(K), .SQRT_BITS(1), .DIV_BITS(1), .RULE(RULE), .ARCH(ARCH),
                  .EN_SPRINGS(EN_SPRINGS), .DEBUG(1'b1)) u0 (
        .clk(clk), .reset(reset), .cfg_we(cfg_we), .cfg_addr(cfg_addr), .cfg_data(cfg_data), .step(step),
        .busy(busy0), .frame_done(fd0), .irq(irq0), .mouse_x(mouse_x), .mouse_y(mouse_y), .mouse_z({W{1'b0}}),
        .mouse_down(mouse_down), .rd_addr(rd_addr), .rd_x(x0), .rd_y(y0), .rd_z(z0), .dbg(dbg0));
    strand_core #(.W(W), .F(F), .M(M), .K(K), .SQRT_BITS(1), .DIV_BITS(1), .RULE(RULE), .ARCH(ARCH),
                  .EN_SPRINGS(EN_SPRINGS), .DEBUG(1'b1)) u1 (
        .clk(clk), .reset(reset), .cfg_we(cfg_we), .cfg_addr(cfg_addr), .cfg_data(cfg_data), .step(step),
        .busy(busy1), .frame_done(fd1), .irq(irq1), .mouse_x(mouse_x), .mouse_y(mouse_y), .mouse_z({W{1'b0}}),
        .mouse_down(mouse_down), .rd_addr(rd_addr), .rd_x(x1), .rd_y(y1), .rd_z(z1), .dbg(dbg1));

    // one reset cycle first, then none: what follows is the same for both copies
    reg f_init = 1'b1, after = 1'b0;
    always @(posedge clk) begin
        f_init <= 1'b0;
        after  <= 1'b1;
    end
    always @* assume (reset == f_init);

    // the documented order (strand_core.v header): the nodes are laid out (CMD = 1) before
    // the first step. A step before that computes from storage that is not reset (the read
    // port's "0 for a node not written" does not cover the frame's own reads), so the
    // outputs would then depend on the state before the reset: assumed away.
    reg laid_out = 1'b0;
    always @(posedge clk) if (cfg_we && cfg_addr == `STRAND_REG_CMD && cfg_data[0] && !reset) laid_out <= 1'b1;
    always @* if (!laid_out) assume (!step);

    reg first = 1'b1;
    always @(posedge clk) if (after) first <= 1'b0;
    always @* if (after) begin
        assert (busy0 == busy1 && fd0 == fd1 && irq0 == irq1);
        assert (x0 == x1 && y0 == y1 && z0 == z1);
        assert (dbg0[CTL_W-1:0] == dbg1[CTL_W-1:0]);   // phase, FV, FEC, walk, lane valid bits and indices
        for (u = 0; u < M; u = u + 1)                    // a lane's data when its valid bit is set
            if (dbg0[LV + u]) assert (dbg0[CTL_W + u*W +: W] == dbg1[CTL_W + u*W +: W] &&
                                      dbg0[CTL_W + (M+u)*W +: W] == dbg1[CTL_W + (M+u)*W +: W] &&
                                      dbg0[CTL_W + (2*M+u)*W +: W] == dbg1[CTL_W + (2*M+u)*W +: W]);
        if (first) assert (!busy0 && !fd0 && !irq0 && dbg0[2:0] == 3'd0 && x0 == 0 && y0 == 0);
    end
endmodule

`resetall
