// axil_props - AXI4-Lite protocol properties of rtl/strand_axil.v (a wrapper top; the core
// is tb/formal/stub_strand_core.v, whose outputs are free). Run by tb/formal/axil.sby.
//
// Assumed of the master (AXI4-Lite, ARM IHI 0022): no VALID in or right after a reset;
// a VALID stays high, with its address, data and strobes unchanged, until its READY.
// Checked of the shell:
//   - a write response (BVALID) comes only for an accepted write, exactly one per write,
//     the cycle after it is accepted; AWREADY and WREADY come together and only with
//     AWVALID and WVALID; a read response exactly two cycles after its read is
//     accepted, one per read; at most one of each outstanding; no read accepted while one is;
//   - BVALID / RVALID stay high, with BRESP / RRESP / RDATA unchanged, until BREADY / RREADY;
//   - every response is OKAY or SLVERR, as the header documents: a write without all
//     byte strobes, a write to a read-only or missing register, a CMD write or a CTRL
//     start while the core is busy, a read of a write-only register or of a node that
//     does not exist: SLVERR (with RDATA 0); a whole write to MOUSE_X, a read of INFO
//     ({DIM, F, W, 0}) or NODES ({M, K}): OKAY;
//   - after a reset: BVALID, RVALID and irq low, ARREADY high.
`default_nettype none

`include "strand_regs.vh"

module axil_props #(
    parameter integer W = 16,
    parameter integer F = 8,
    parameter integer M = 2,
    parameter integer K = 3
) (
    input wire        clk,
    input wire        reset,
    input wire [12:0] awaddr,
    input wire [2:0]  awprot,
    input wire        awvalid,
    input wire [31:0] wdata,
    input wire [3:0]  wstrb,
    input wire        wvalid,
    input wire        bready,
    input wire [12:0] araddr,
    input wire [2:0]  arprot,
    input wire        arvalid,
    input wire        rready
);
    localparam integer UW = M > 1 ? $clog2(M) : 1;
    localparam integer IW = K > 1 ? $clog2(K) : 1;
    localparam integer AW = UW + IW;
    localparam integer NB = 12 > AW + 4 ? 12 : AW + 4;
    localparam integer XA = NB + 1;               // the shell's address bits
    localparam [1:0] OKAY = 2'b00, SLVERR = 2'b10;

    wire        awready, wready, bvalid, arready, rvalid, irq;
    wire [1:0]  bresp, rresp;
    wire [31:0] rdata;
    strand_axil #(.W(W), .F(F), .M(M), .K(K)) dut (
        .clk(clk), .reset(reset),
        .s_axil_awaddr(awaddr[XA-1:0]), .s_axil_awprot(awprot), .s_axil_awvalid(awvalid), .s_axil_awready(awready),
        .s_axil_wdata(wdata), .s_axil_wstrb(wstrb), .s_axil_wvalid(wvalid), .s_axil_wready(wready),
        .s_axil_bresp(bresp), .s_axil_bvalid(bvalid), .s_axil_bready(bready),
        .s_axil_araddr(araddr[XA-1:0]), .s_axil_arprot(arprot), .s_axil_arvalid(arvalid), .s_axil_arready(arready),
        .s_axil_rdata(rdata), .s_axil_rresp(rresp), .s_axil_rvalid(rvalid), .s_axil_rready(rready),
        .irq(irq));

    reg f_init = 1'b1;
    always @(posedge clk) f_init <= 1'b0;
    always @* if (f_init) assume (reset);
    always @* assume ((awaddr >> XA) == 0 && (araddr >> XA) == 0);   // the shell has XA address bits

    // ---- the master ----
    reg        reset_prev;
    reg        awvalid_p, wvalid_p, arvalid_p, awready_p, wready_p, arready_p;
    reg [12:0] awaddr_p, araddr_p;
    reg [31:0] wdata_p;
    reg [3:0]  wstrb_p;
    always @(posedge clk) begin
        reset_prev <= reset;
        {awvalid_p, wvalid_p, arvalid_p} <= {awvalid, wvalid, arvalid};
        {awready_p, wready_p, arready_p} <= {awready, wready, arready};
        {awaddr_p, araddr_p, wdata_p, wstrb_p} <= {awaddr, araddr, wdata, wstrb};
    end
    always @* begin
        if (reset || reset_prev) assume (!awvalid && !wvalid && !arvalid);
        if (!f_init && !reset_prev && !reset) begin
            if (awvalid_p && !awready_p) assume (awvalid && awaddr == awaddr_p);
            if (wvalid_p && !wready_p)   assume (wvalid && wdata == wdata_p && wstrb == wstrb_p);
            if (arvalid_p && !arready_p) assume (arvalid && araddr == araddr_p);
        end
    end

    // ---- the requests the shell accepted, and what the documented answer is ----
    wire w_acc = awvalid && awready;             // (== wvalid && wready, checked below)
    wire r_acc = arvalid && arready;
    reg  [1:0] wpend, rpend;                     // accepted and not yet answered
    reg  [2:0] r_age;                            // cycles since the read was accepted (to 4)
    reg        b_prev_valid, b_prev_ready, r_prev_valid, r_prev_ready;
    reg  [1:0] bresp_p, rresp_p;
    reg [31:0] rdata_p;
    reg  [1:0] w_expect, r_expect;               // 1 OKAY, 2 SLVERR, 0 either (not pinned by the header)
    reg [31:0] r_expect_data;
    reg        r_check_data;

    // the shell's busy_soon (the core busy, or a frame or a CMD on its way to it): the .sby
    // script makes it a port of strand_axil (yosys expose) and connects it here
    wire        busy_now;
    wire [12:0] wa = awaddr;
    wire [12:0] ra = araddr;
    wire        w_reg_win = wa < 13'h100;                                  // the core's registers
    wire [5:0]  w_reg     = wa[7:2];
    wire        w_load    = w_reg == `STRAND_REG_CMD || w_reg == `STRAND_REG_NODE || w_reg == `STRAND_REG_EDGE;
    wire        r_node    = ra[NB];
    wire [31:0] r_n       = ra[4 +: AW];
    wire        r_node_ok = ra[4 +: IW] < K && ra[4 + IW +: UW] < M && (ra[NB-1:0] >> (4 + AW)) == 0;

    always @(posedge clk) begin
        b_prev_valid <= bvalid; b_prev_ready <= bready; bresp_p <= bresp;
        r_prev_valid <= rvalid; r_prev_ready <= rready; rresp_p <= rresp; rdata_p <= rdata;
        if (reset) begin
            wpend <= 2'd0;
            rpend <= 2'd0;
            r_age <= 3'd0;
        end else begin
            wpend <= wpend + (w_acc ? 2'd1 : 2'd0) - (bvalid && bready ? 2'd1 : 2'd0);
            rpend <= rpend + (r_acc ? 2'd1 : 2'd0) - (rvalid && rready ? 2'd1 : 2'd0);
            r_age <= r_acc ? 3'd1 : (r_age != 0 && r_age != 3'd4 ? r_age + 3'd1 : r_age);
        end
        if (w_acc) begin
            if (wstrb != 4'hF)                             w_expect <= 2'd2;
            else if (wa == 13'h108 || wa == 13'h10C || wa == 13'h110) w_expect <= 2'd2;  // read only
            else if (wa[NB])                               w_expect <= 2'd2;  // the node window
            else if (wa == 13'h100 && wdata[0] && busy_now) w_expect <= 2'd2; // a start while busy
            else if (w_reg_win && wa[1:0] == 2'b00 && w_load && busy_now) w_expect <= 2'd2; // CMD, NODE, EDGE while busy
            else if (wa[1:0] != 2'b00)                     w_expect <= 2'd2;
            else if (wa == 13'h114)                        w_expect <= 2'd1;  // MOUSE_X
            else if (w_reg_win && w_reg < `STRAND_REG_COUNT && !w_load) w_expect <= 2'd1;
            else                                           w_expect <= 2'd0;
        end
        if (r_acc) begin
            r_check_data <= 1'b0;
            if (ra < 13'h100)           r_expect <= 2'd2;      // the core's registers: write only
            else if (ra == 13'h100)     r_expect <= 2'd2;      // CTRL: write only
            else if (ra == 13'h10C) begin
                r_expect <= 2'd1; r_check_data <= 1'b1; r_expect_data <= {DIM8, F8, W8, 8'd0};
            end else if (ra == 13'h110) begin
                r_expect <= 2'd1; r_check_data <= 1'b1; r_expect_data <= {M16, K16};
            end else if (r_node && ra[1:0] == 2'b00 && !r_node_ok) r_expect <= 2'd2;
            else if (r_node && ra[3:2] == 2'd3) r_expect <= 2'd2;   // axis 3
            else if (r_node && ra[3:2] == 2'd2) r_expect <= 2'd2;   // z in 2D
            else                        r_expect <= 2'd0;
        end
    end
    localparam [7:0]  DIM8 = 8'd2, F8 = F[7:0], W8 = W[7:0];
    localparam [15:0] M16 = M[15:0], K16 = K[15:0];
    wire unused = &{1'b0, r_n};

    always @* if (!f_init) begin
        if (reset_prev) begin
            assert (!bvalid && !rvalid && !irq && arready);
        end else begin
            assert (awready == wready);
            if (awready) assert (awvalid && wvalid);
            assert (wpend <= 2'd1 && rpend <= 2'd1);
            assert (bvalid == (wpend == 2'd1));
            // the answer three cycles after the read is accepted (the core's read port takes two)
            assert (rvalid == (rpend == 2'd1 && r_age == 3'd3 || rpend == 2'd1 && r_age == 3'd4));
            if (rpend == 2'd1) assert (!arready);
            if (b_prev_valid && !b_prev_ready) assert (bvalid && bresp == bresp_p);
            if (r_prev_valid && !r_prev_ready) assert (rvalid && rresp == rresp_p && rdata == rdata_p);
            assert (bresp == OKAY || bresp == SLVERR);
            assert (rresp == OKAY || rresp == SLVERR);
            if (bvalid && w_expect == 2'd1) assert (bresp == OKAY);
            if (bvalid && w_expect == 2'd2) assert (bresp == SLVERR);
            if (rvalid && r_expect == 2'd1) assert (rresp == OKAY);
            if (rvalid && r_expect == 2'd2) assert (rresp == SLVERR && rdata == 32'd0);
            if (rvalid && r_check_data) assert (rdata == r_expect_data);
        end
        cover (bvalid && bresp == SLVERR);
        cover (rvalid && rresp == OKAY && r_check_data);
    end
endmodule

`resetall
