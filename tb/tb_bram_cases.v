`default_nettype none
`timescale 1ns / 1ps

/*
 * tb_bram_cases - tb/bram_cases.v as written (the RTL) and as Yosys maps it to the ECP5's
 * cells (module bram_cases_net: DP16KD blocks simulated by tb/ecp5_dp16kd.v), side by side
 * on the same random writes and reads for CYCLES cycles; every read bit the RTL defines
 * (an unwritten word reads x in the RTL) must match. Addresses come mostly from a pool of 64
 * (so that words are read after they are written) and a read address equals the write
 * address one cycle in four (reads of the word being written). Prints PASS or FAIL with the
 * first difference; a run that compared few bits fails too.
 */
module tb_bram_cases;
    parameter integer CYCLES = 20000;
    parameter integer SEED = 1;

    reg clk = 1'b0;
    reg we = 1'b0, re = 1'b0;
    reg [13:0] waddr = 14'd0, raddr = 14'd0;
    reg [35:0] wdata = 36'd0;
    reg [1:0] wbe = 2'b00;
    localparam integer OUT = 36 + 18 + 18 + 9 + 4 + 1 + 18 + 18 + 18;
    wire [OUT-1:0] rtl_out, net_out;

    bram_cases u_rtl (
        .clk(clk), .we(we), .waddr(waddr), .wdata(wdata), .wbe(wbe), .re(re), .raddr(raddr),
        .rd_pdp36(rtl_out[35:0]), .rd_be18(rtl_out[53:36]), .rd_old18(rtl_out[71:54]),
        .rd_new9(rtl_out[80:72]), .rd_nib4(rtl_out[84:81]), .rd_bit1(rtl_out[85]),
        .rd_tdp_a(rtl_out[103:86]), .rd_tdp_b(rtl_out[121:104]), .rd_init18(rtl_out[139:122]));
    bram_cases_net u_net (
        .clk(clk), .we(we), .waddr(waddr), .wdata(wdata), .wbe(wbe), .re(re), .raddr(raddr),
        .rd_pdp36(net_out[35:0]), .rd_be18(net_out[53:36]), .rd_old18(net_out[71:54]),
        .rd_new9(net_out[80:72]), .rd_nib4(net_out[84:81]), .rd_bit1(net_out[85]),
        .rd_tdp_a(net_out[103:86]), .rd_tdp_b(net_out[121:104]), .rd_init18(net_out[139:122]));

    integer seed, cycle, b, compared;
    reg [13:0] pool [0:63];
    function [13:0] pick_addr(input integer r);
        pick_addr = (r & 3) == 0 ? $random(seed) : pool[(r >> 2) & 63];
    endfunction

    initial begin
        seed = SEED;
        compared = 0;
        for (b = 0; b < 64; b = b + 1) pool[b] = $random(seed);
        for (cycle = 0; cycle < CYCLES; cycle = cycle + 1) begin
            // inputs change away from the clock edge
            we = ($random(seed) & 3) != 0;
            re = ($random(seed) & 7) != 0;
            waddr = pick_addr($random(seed));
            raddr = ($random(seed) & 3) == 0 ? waddr : pick_addr($random(seed));
            wdata = {$random(seed), $random(seed)};
            wbe = $random(seed);
            #5 clk = 1'b1;
            #1;
            for (b = 0; b < OUT; b = b + 1)
                if (rtl_out[b] === 1'b0 || rtl_out[b] === 1'b1) begin
                    compared = compared + 1;
                    if (net_out[b] !== rtl_out[b]) begin
                        $display("FAIL bram_cases: cycle %0d, output bit %0d: RTL %b, netlist %b (RTL %h, netlist %h)",
                                 cycle, b, rtl_out[b], net_out[b], rtl_out, net_out);
                        $finish;
                    end
                end
            #4 clk = 1'b0;
        end
        if (compared < CYCLES * OUT / 2) begin
            $display("FAIL bram_cases: only %0d of %0d read bits were defined in the RTL", compared, CYCLES * OUT);
            $finish;
        end
        $display("PASS bram_cases: %0d cycles, %0d read bits of the netlist equal to the RTL's", CYCLES, compared);
        $finish;
    end
endmodule

`resetall
