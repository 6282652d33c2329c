`default_nettype none
`timescale 1ns / 1ps

`include "strand_defs.vh"
`include "strand_regs.vh"

/*
 * strand_axil - strand_core behind an AXI4-Lite slave (32-bit data), the bus Vivado
 * and Quartus bridges and LiteX accept, with a level interrupt.
 *
 * Address map (byte addresses; every register is a 32-bit word at a multiple of 4):
 *   0x000 + 4 a   the core's register a (scripts/gen_regs.py: GDT2_X at 0x000, ...,
 *                 IRQ_ACK at 0x084): write only; a write passes cfg_data = wdata[W-1:0]
 *                 to the core. CMD, NODE and EDGE act only while the core is idle: such
 *                 a write while busy is answered SLVERR and does nothing. The run-time
 *                 constants may be written at any time and act two cycles after the
 *                 write is accepted (see Channels).
 *   0x100 CTRL    write bit 0 = 1: start a frame (SLVERR while busy, nothing done);
 *                 bit 1: the interrupt enable (read back in STATUS)
 *   0x104 STATUS  read: bit 0 busy, bit 1 frame done since the last clear (the core's
 *                 irq), bit 2 interrupt enable; write 1 to bit 1: clear it (IRQ_ACK)
 *   0x108 FRAMES  read: frames finished since reset (wraps at 2^32)
 *   0x10C INFO    read: {DIM[7:0], F[7:0], W[7:0], 8'd0}; 0x110 NODES: {M[15:0], K[15:0]}
 *   0x114 MOUSE_X, 0x118 MOUSE_Y, 0x11C MOUSE_Z, 0x120 MOUSE_DOWN (bit 0): read/write,
 *                 the core's mouse inputs (it samples them when a frame starts)
 *   NODE_BASE + 16 n + 4 k   read: axis k (0 x, 1 y, 2 z) of the node at {unit, node}
 *                 address n, sign-extended from W bits; NODE_BASE = 2^AXIL_NB, AXIL_NB
 *                 = max(12, AW + 4) (0x1000 up to 256 nodes); AXIL_AW = AXIL_NB + 1 address bits
 * Any other access is answered SLVERR and does nothing: a read of a write-only or
 * missing register, a write to a read-only one, a node that does not exist, axis 3,
 * a z axis in 2D. A write whose byte strobes are not all set is answered SLVERR and
 * not done (every register is written whole).
 *
 * Channels: a write is accepted when its address and data are both valid and the
 * response channel is free (AWREADY = WREADY in that cycle), one per cycle while
 * BREADY is high; its response follows in the next cycle. The write is decoded in the
 * cycle it is accepted into a local register stage (which register, the data) and done
 * from that stage one cycle later: the decode's fan-out (every register's enable) and the
 * registers it feeds, which sit beside their readers across the device, are then never
 * on one path (it was the q10_4x256 build's critical path, 8 ns of its 11 in routing).
 * So a write takes effect two cycles after it is accepted. A read is accepted when
 * the read channel is free; its data follow three cycles later (the core's read port
 * has two cycles of latency). Reads and writes proceed independently.
 *
 * irq = the core's frame-done interrupt and the enable: a level, high until STATUS
 * bit 1 is written 1.
 */
module strand_axil #(
`include "strand_params.vh"
) (
    input  wire              clk,
    input  wire              reset,          // synchronous, active high

    input  wire [AXIL_AW-1:0] s_axil_awaddr,
    input  wire [2:0]        s_axil_awprot,
    input  wire              s_axil_awvalid,
    output wire              s_axil_awready,
    input  wire [31:0]       s_axil_wdata,
    input  wire [3:0]        s_axil_wstrb,
    input  wire              s_axil_wvalid,
    output wire              s_axil_wready,
    output reg  [1:0]        s_axil_bresp,
    output reg               s_axil_bvalid,
    input  wire              s_axil_bready,

    input  wire [AXIL_AW-1:0] s_axil_araddr,
    input  wire [2:0]        s_axil_arprot,
    input  wire              s_axil_arvalid,
    output wire              s_axil_arready,
    output reg  [31:0]       s_axil_rdata,
    output reg  [1:0]        s_axil_rresp,
    output reg               s_axil_rvalid,
    input  wire              s_axil_rready,

    output wire              irq
);

    localparam integer NB = AXIL_NB;      // the node window: addresses with bit NB set
    localparam integer ADDR_W = AXIL_AW;

    localparam [1:0] OKAY = 2'b00, SLVERR = 2'b10;
    localparam integer RB = `STRAND_REG_ADDR_BITS;
    localparam [ADDR_W-1:0] A_CTRL = 'h100, A_STATUS = 'h104, A_FRAMES = 'h108, A_INFO = 'h10C, A_NODES = 'h110,
                            A_MOUSE_X = 'h114, A_MOUSE_Y = 'h118, A_MOUSE_Z = 'h11C, A_MOUSE_DOWN = 'h120;
    localparam integer REG_COUNT = `STRAND_REG_COUNT;
    localparam [UW:0] M_COUNT = M[UW:0];
    localparam [IW:0] K_COUNT = K[IW:0];
    localparam [7:0]  DIM8 = DIM[7:0], F8 = F[7:0], W8 = W[7:0];
    localparam [15:0] M16 = M[15:0], K16 = K[15:0];
    localparam [RB:0] REG_END = REG_COUNT[RB:0];

    // ---- the core ----
    reg            cfg_we;
    reg  [RB-1:0]  cfg_addr;
    reg  [W-1:0]   cfg_data;
    reg            step;          // a CTRL write's step, in the cycle after the write
    reg            step_to_core;  // the same, one cycle later: its own register beside frame_ctrl
    reg  [W-1:0]   mouse_x, mouse_y, mouse_z;
    reg            mouse_down, irq_en;
    reg  [31:0]    frames;
    wire           busy, frame_done, core_irq;
    wire [W-1:0]   rd_x, rd_y, rd_z;
    wire [AW-1:0]  rd_node = s_axil_araddr[4 +: AW];  // the core samples it in the cycle a read is accepted
    /* verilator lint_off PINCONNECTEMPTY */
    // the observation port is for simulation (DEBUG)
    strand_core #(
`include "strand_params_pass.vh"
    ) u_core (
        .clk(clk), .reset(reset), .cfg_we(cfg_we), .cfg_addr(cfg_addr), .cfg_data(cfg_data),
        .step(step_to_core), .busy(busy), .frame_done(frame_done), .irq(core_irq),
        .mouse_x(mouse_x), .mouse_y(mouse_y), .mouse_z(mouse_z), .mouse_down(mouse_down),
        .rd_addr(rd_node), .rd_x(rd_x), .rd_y(rd_y), .rd_z(rd_z), .dbg());
    /* verilator lint_on PINCONNECTEMPTY */
    assign irq = core_irq && irq_en;

    // ---- writes ----
    wire          do_write = s_axil_awvalid && s_axil_wvalid && (!s_axil_bvalid || s_axil_bready);
    wire [ADDR_W-1:0] wa   = s_axil_awaddr;
    wire          w_whole  = &s_axil_wstrb;
    wire          w_cfg    = wa[ADDR_W-1:RB+2] == {(ADDR_W-RB-2){1'b0}} && wa[1:0] == 2'b00 && {1'b0, wa[RB+1:2]} < REG_END;
    wire [RB-1:0] w_reg    = wa[RB+1:2];
    // CMD, NODE and EDGE load the body: the core ignores them while busy, so they are refused;
    // so is a step. busy_soon also counts a step or a CMD on its way to the core.
    // the write stage: a write decoded in the cycle it is accepted, done in the next one
    reg            wq_cfg, wq_ctrl, wq_irq_ack, wq_step;
    reg  [3:0]     wq_mouse;      // MOUSE_X, _Y, _Z, _DOWN
    reg  [RB-1:0]  wq_reg;
    reg  [W-1:0]   wq_data;
    wire          busy_soon = busy || step || step_to_core || wq_step || (cfg_we && cfg_addr == `STRAND_REG_CMD)
                           || (wq_cfg && wq_reg == `STRAND_REG_CMD);
    wire          w_load   = w_reg == `STRAND_REG_CMD || w_reg == `STRAND_REG_NODE || w_reg == `STRAND_REG_EDGE;
    wire          w_ok_cfg = w_cfg && !(w_load && busy_soon);
    wire          w_ctrl   = wa == A_CTRL && !(s_axil_wdata[0] && busy_soon);
    wire          w_mouse  = wa == A_MOUSE_X || wa == A_MOUSE_Y || (DIM == 3 && wa == A_MOUSE_Z) || wa == A_MOUSE_DOWN;
    wire          w_ok     = w_whole && (w_ok_cfg || w_ctrl || wa == A_STATUS || w_mouse);
    assign s_axil_awready = do_write;
    assign s_axil_wready  = do_write;

    // accepted: the response, and the decode into the write stage
    always @(posedge clk) begin
        wq_cfg     <= 1'b0;
        wq_ctrl    <= 1'b0;
        wq_irq_ack <= 1'b0;
        wq_step    <= 1'b0;
        wq_mouse   <= 4'd0;
        if (reset) begin
            s_axil_bvalid <= 1'b0;
            s_axil_bresp  <= OKAY;
            wq_reg        <= {RB{1'b0}};
            wq_data       <= {W{1'b0}};
        end else begin
            if (s_axil_bvalid && s_axil_bready) s_axil_bvalid <= 1'b0;
            if (do_write) begin
                s_axil_bvalid <= 1'b1;
                s_axil_bresp  <= w_ok ? OKAY : SLVERR;
                wq_cfg        <= w_ok && w_ok_cfg;
                wq_ctrl       <= w_ok && wa == A_CTRL;
                wq_step       <= w_ok && wa == A_CTRL && s_axil_wdata[0];
                wq_irq_ack    <= w_ok && wa == A_STATUS && s_axil_wdata[1];  // clear the frame-done flag
                wq_mouse      <= {4{w_ok}} & {wa == A_MOUSE_DOWN, wa == A_MOUSE_Z, wa == A_MOUSE_Y, wa == A_MOUSE_X};
                wq_reg        <= w_reg;
                wq_data       <= s_axil_wdata[W-1:0];
            end
        end
    end

    // the write stage done: one register's enable from one flip-flop, no decode
    always @(posedge clk) begin
        cfg_we <= 1'b0;
        step   <= 1'b0;
        if (reset) begin
            cfg_addr   <= {RB{1'b0}};
            cfg_data   <= {W{1'b0}};
            mouse_x    <= {W{1'b0}};
            mouse_y    <= {W{1'b0}};
            mouse_z    <= {W{1'b0}};
            mouse_down <= 1'b0;
            irq_en     <= 1'b0;
        end else begin
            if (wq_cfg) begin
                cfg_we   <= 1'b1;
                cfg_addr <= wq_reg;
                cfg_data <= wq_data;
            end
            if (wq_ctrl) begin
                step   <= wq_step;
                irq_en <= wq_data[1];
            end
            if (wq_irq_ack) begin
                cfg_we   <= 1'b1;
                cfg_addr <= `STRAND_REG_IRQ_ACK;
            end
            if (wq_mouse[0]) mouse_x <= wq_data;
            if (wq_mouse[1]) mouse_y <= wq_data;
            if (wq_mouse[2]) mouse_z <= wq_data;
            if (wq_mouse[3]) mouse_down <= wq_data[0];
        end
    end

    // step reaches the core through a second register, so that place and route can put one
    // beside the bus and one beside frame_ctrl: the step net crossed the device in one cycle
    // (the 2x256 pipelined build's critical path, 11.4 ns of its 15.5 ns in routing)
    always @(posedge clk) step_to_core <= step && !reset;

    always @(posedge clk) begin
        if (reset) frames <= 32'd0;
        else if (frame_done) frames <= frames + 1'b1;
    end

    // ---- reads: accepted when the read channel is free, answered three cycles later ----
    reg               rd_wait;     // a read was accepted in the last cycle
    reg               rd_pending;  // a read was accepted two cycles ago: the core's data arrive now
    reg  [ADDR_W-1:0] ra_q;
    reg               ra_node_q;   // it reads a node
    assign s_axil_arready = !rd_wait && !rd_pending && !s_axil_rvalid;
    wire do_read = s_axil_arvalid && s_axil_arready;

    wire [ADDR_W-1:0] ra = s_axil_araddr;
    wire              ra_node = ra[NB] && ra[1:0] == 2'b00;  // the top address bit: the node window

    function [31:0] sext(input [W-1:0] v);
        /* verilator lint_off UNUSEDSIGNAL */
        reg [W+31:0] wide;  // v sign-extended past 32 bits; the low 32 are the answer
        /* verilator lint_on UNUSEDSIGNAL */
        begin
            wide = {{32{v[W-1]}}, v};
            sext = wide[31:0];
        end
    endfunction

    // the answer to the read in ra_q, two cycles after it was accepted
    reg [31:0] r_data;
    reg        r_ok;
    wire [UW-1:0] ru = ra_q[4+IW +: UW];
    wire [IW-1:0] rn = ra_q[4 +: IW];
    wire [NB-1:0] r_off = ra_q[NB-1:0];
    wire          node_exists = {1'b0, ru} < M_COUNT && {1'b0, rn} < K_COUNT && (r_off >> (4 + AW)) == {NB{1'b0}};
    always @* begin
        r_data = 32'd0;
        r_ok   = 1'b1;
        if (ra_node_q) begin
            r_ok = node_exists && (ra_q[3:2] == 2'd0 || ra_q[3:2] == 2'd1 || (DIM == 3 && ra_q[3:2] == 2'd2));
            r_data = ra_q[3:2] == 2'd0 ? sext(rd_x) : ra_q[3:2] == 2'd1 ? sext(rd_y) : sext(rd_z);
        end else begin
            case (ra_q)
                A_STATUS:     r_data = {29'd0, irq_en, core_irq, busy || wq_step || step || step_to_core};  // busy from the step's write on
                A_FRAMES:     r_data = frames;
                A_INFO:       r_data = {DIM8, F8, W8, 8'd0};
                A_NODES:      r_data = {M16, K16};
                A_MOUSE_X:    r_data = sext(mouse_x);
                A_MOUSE_Y:    r_data = sext(mouse_y);
                A_MOUSE_Z:    begin r_data = sext(mouse_z); r_ok = DIM == 3; end
                A_MOUSE_DOWN: r_data = {31'd0, mouse_down};
                default:      r_ok = 1'b0;
            endcase
        end
    end

    always @(posedge clk) begin
        if (reset) begin
            rd_wait       <= 1'b0;
            rd_pending    <= 1'b0;
            ra_q          <= {ADDR_W{1'b0}};
            ra_node_q     <= 1'b0;
            s_axil_rvalid <= 1'b0;
            s_axil_rresp  <= OKAY;
            s_axil_rdata  <= 32'd0;
        end else begin
            rd_wait    <= do_read;
            rd_pending <= rd_wait;
            if (do_read) begin
                ra_q      <= ra;
                ra_node_q <= ra_node;
            end
            if (s_axil_rvalid && s_axil_rready) s_axil_rvalid <= 1'b0;
            if (rd_pending) begin
                s_axil_rvalid <= 1'b1;
                s_axil_rresp  <= r_ok ? OKAY : SLVERR;
                s_axil_rdata  <= r_ok ? r_data : 32'd0;
            end
        end
    end

    wire unused_axil = &{1'b0, s_axil_awprot, s_axil_arprot, s_axil_wdata};  // protection is not used

endmodule

`resetall
