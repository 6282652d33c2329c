`default_nettype none
`timescale 1ns / 1ps

/*
 * bram_cases - memories in the forms Yosys maps to the ECP5's DP16KD, one of each: the check of
 * tb/ecp5_dp16kd.v (scripts/bram_check.py). Yosys maps this module to ECP5 cells; the bench
 * (tb/tb_bram_cases.v) runs the RTL and that netlist side by side on random writes and reads
 * and compares every read, so the model, driven as Yosys's mapping drives it, must give what
 * the RTL says: the 36-bit pseudo dual port (the form Strand's node memories take), byte
 * enables at 18 bits, the read before write and the write-through of one port at 18 and 9
 * bits, the narrow widths 4 and 1, two write ports, and initial contents.
 */
module bram_cases (
    input  wire        clk,
    input  wire        we,
    input  wire [13:0] waddr,
    input  wire [35:0] wdata,
    input  wire [1:0]  wbe,
    input  wire        re,
    input  wire [13:0] raddr,
    output reg  [35:0] rd_pdp36,   // 36 x 512, one write port, one read port
    output reg  [17:0] rd_be18,    // 18 x 1024 with two byte enables
    output reg  [17:0] rd_old18,   // 18 x 1024, one port: read before write
    output reg  [8:0]  rd_new9,    // 9 x 2048, one port: the written word read back (write-through)
    output reg  [3:0]  rd_nib4,    // 4 x 4096
    output reg  [0:0]  rd_bit1,    // 1 x 16384
    output reg  [17:0] rd_tdp_a,   // 18 x 1024, two ports that both write and read
    output reg  [17:0] rd_tdp_b,
    output reg  [17:0] rd_init18   // 18 x 1024 with initial contents
);
    (* ram_style = "block" *) reg [35:0] pdp36 [0:511];
    always @(posedge clk) begin
        if (we) pdp36[waddr[8:0]] <= wdata;
        if (re) rd_pdp36 <= pdp36[raddr[8:0]];
    end

    (* ram_style = "block" *) reg [17:0] be18 [0:1023];
    always @(posedge clk) begin
        if (we && wbe[0]) be18[waddr[9:0]][8:0] <= wdata[8:0];
        if (we && wbe[1]) be18[waddr[9:0]][17:9] <= wdata[17:9];
        if (re) rd_be18 <= be18[raddr[9:0]];
    end

    (* ram_style = "block" *) reg [17:0] old18 [0:1023];
    always @(posedge clk) begin
        if (we) old18[waddr[9:0]] <= wdata[17:0];
        if (re) rd_old18 <= old18[waddr[9:0]];   // the write's own address: the old word
    end

    (* ram_style = "block" *) reg [8:0] new9 [0:2047];
    always @(posedge clk) if (re) begin
        if (we) begin
            new9[waddr[10:0]] <= wdata[8:0];
            rd_new9 <= wdata[8:0];
        end else
            rd_new9 <= new9[waddr[10:0]];
    end

    (* ram_style = "block" *) reg [3:0] nib4 [0:4095];
    always @(posedge clk) begin
        if (we) nib4[waddr[11:0]] <= wdata[3:0];
        if (re) rd_nib4 <= nib4[raddr[11:0]];
    end

    (* ram_style = "block" *) reg [0:0] bit1 [0:16383];
    always @(posedge clk) begin
        if (we) bit1[waddr] <= wdata[0];
        if (re) rd_bit1 <= bit1[raddr];
    end

    // two ports, each writing the half of the memory its address's top bit names (so that
    // they never write one word together) and reading its own address
    (* ram_style = "block" *) reg [17:0] tdp [0:1023];
    always @(posedge clk) begin
        if (we) tdp[{1'b0, waddr[8:0]}] <= wdata[17:0];
        if (re) rd_tdp_a <= tdp[{1'b0, waddr[8:0]}];
    end
    always @(posedge clk) begin
        if (we) tdp[{1'b1, raddr[8:0]}] <= wdata[35:18];
        if (re) rd_tdp_b <= tdp[{1'b1, raddr[8:0]}];
    end

    (* ram_style = "block" *) reg [17:0] init18 [0:1023];
    integer i;
    initial for (i = 0; i < 1024; i = i + 1) init18[i] = i[17:0] * 18'd4099 ^ 18'h2a5a5;
    always @(posedge clk) begin
        if (we && waddr[13]) init18[waddr[9:0]] <= wdata[17:0];   // now and then: most words keep their initial value
        if (re) rd_init18 <= init18[raddr[9:0]];
    end
endmodule

`resetall
