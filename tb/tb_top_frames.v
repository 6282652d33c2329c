`default_nettype none
`timescale 1ns / 1ps

`include "strand_regs.vh"
`include "params.vh"

/*
 * tb_top_frames - strand_core against the C frame engine, frame by frame.
 *
 * sim_top (strand_core with its observation port unpacked) is built from the
 * params.vh that `strand hwgen SCENE DIR` writes (the build), with config.hex (the setup
 * writes), mouse.hex (the pointer per frame) and expected.hex (every node's
 * position at every frame end, from the fixed-point frame engine). This bench
 * resets the top, writes the setup, then for every frame: drives the mouse,
 * pulses step, counts the cycles to frame_done (they must equal the formula of
 * docs/architecture.md, STRAND_CYCLES_PER_FRAME), reads every node through the
 * read port and compares x, y and z bit for bit; from the first reset on, no output
 * may ever be X. The status of every cycle of a frame, from the step edge to the
 * cycle frame_done shows in, is checked against status.hex (the cycle model's
 * prediction for this protocol, written by `strand hwgen`): the cycles FV and FEC are
 * high, the first cycle FEC is high, and a signature of {phase, FV, FEC, busy, irq,
 * frame_done, uidx, nidx, counter} over every cycle. It prints one PASS or FAIL line;
 * a FAIL names the frame, the node, the axis and both values (or the status that differs).
 */
module tb_top_frames #(
    parameter HW_DIR = "."   // where `strand hwgen` wrote the .hex files (the FuseSoC sim target sets it)
);
`include "strand_params_scene_local.vh"
    localparam integer N = M * K;
    localparam integer FRAMES = `STRAND_FRAMES;
    localparam integer NCONFIG = `STRAND_NCONFIG;
    localparam integer TIMEOUT = 4 * `STRAND_CYCLES_PER_FRAME; // cycles a frame may take before we give up

    reg clk = 1'b0;
    reg reset = 1'b1;
    reg [W-1:0] mouse_x = 0, mouse_y = 0, mouse_z = 0;
    reg mouse_down = 1'b0;
    reg step = 1'b0;
    reg cfg_we = 1'b0;
    reg [`STRAND_REG_ADDR_BITS-1:0] cfg_addr = 0;
    reg [W-1:0] cfg_data = 0;
    reg [UW+IW-1:0] rd_addr = 0;
    wire [W-1:0] rd_x, rd_y, rd_z;
    wire busy, frame_done, irq, fv, fec;
    wire [2:0] phase;
    wire [UW-1:0] uidx;
    wire [IW-1:0] nidx;
    wire [CW-1:0] counter;
    wire [WB-1:0] wb_valid;
    wire [WB*IW-1:0] wb_idx;
    wire [WB*W-1:0] wb_x, wb_y, wb_z;

    sim_top dut (
        .clk(clk), .reset(reset), .mouse_x(mouse_x), .mouse_y(mouse_y), .mouse_z(mouse_z), .mouse_down(mouse_down),
        .step(step), .busy(busy), .frame_done(frame_done), .irq(irq), .cfg_we(cfg_we), .cfg_addr(cfg_addr),
        .cfg_data(cfg_data), .rd_addr(rd_addr), .rd_x(rd_x), .rd_y(rd_y), .rd_z(rd_z), .phase(phase), .fv(fv), .fec(fec),
        .uidx(uidx), .nidx(nidx), .counter(counter),
        .wb_valid(wb_valid), .wb_idx(wb_idx), .wb_x(wb_x), .wb_y(wb_y), .wb_z(wb_z));

    always #5 clk = ~clk;

    // No X may reach an output once reset has been applied (every register starts as X here).
    reg checking_x = 1'b0;
    always @(negedge clk)
        if (checking_x && ^{busy, frame_done, irq, rd_x, rd_y, rd_z, phase, fv, fec, uidx, nidx, counter, wb_valid, wb_idx, wb_x, wb_y,
                            wb_z} === 1'bx) begin
            $display("FAIL tb_top_frames: an output is X at time %0t after reset", $time);
            $fatal(1);
        end

    reg [39:0]  config_mem [0:NCONFIG-1];
    reg [31:0]  mouse_mem  [0:4*FRAMES-1];     // per frame: button, x, y, z
    reg [31:0]  expect_mem [0:3*N*FRAMES-1];   // per frame and node: x, y, z
    reg [31:0]  status_mem [0:4*FRAMES-1];     // per frame: FV cycles, FEC cycles, first FEC cycle, signature

    // The status of the frame under way, sampled as the cycle count is (after every edge from
    // the step edge on), folded as model/hwgen.c folds the cycle model's: FNV-1a's step.
    reg [31:0] fv_n, fec_n, fec_first, sig;
    function [31:0] mix(input [31:0] h, input [31:0] v);
        mix = (h ^ v) * 32'h01000193;
    endfunction
    task automatic sample_status(input integer cycle);
        begin
            fv_n = fv_n + {31'd0, fv};
            fec_n = fec_n + {31'd0, fec};
            if (fec && fec_first == 32'd0) fec_first = cycle;
            sig = mix(sig, {29'd0, phase});
            sig = mix(sig, {27'd0, fv, fec, busy, irq, frame_done});
            sig = mix(sig, {{(32 - UW){1'b0}}, uidx});
            sig = mix(sig, {{(32 - IW){1'b0}}, nidx});
            sig = mix(sig, {{(32 - CW){1'b0}}, counter});
        end
    endtask

    integer frame, node, cycles, errors;
    reg [W-1:0] want_x, want_y, want_z;

    task automatic fail(input [8*64-1:0] why);
        begin
            $display("FAIL tb_top_frames: %0s", why);
            $fatal(1);
        end
    endtask

    initial begin
        errors = 0;
        $readmemh({HW_DIR, "/config.hex"}, config_mem);
        $readmemh({HW_DIR, "/mouse.hex"}, mouse_mem);
        $readmemh({HW_DIR, "/expected.hex"}, expect_mem);
        $readmemh({HW_DIR, "/status.hex"}, status_mem);
        if ($test$plusargs("trace")) begin
            $dumpfile("tb_top_frames.fst");
            $dumpvars(0, tb_top_frames);
        end

        repeat (3) @(posedge clk);
        #1 reset = 1'b0;
        checking_x = 1'b1;
        // the setup: constants, pins, then the nodes (CMD init, or NODE loads) and the edges
        for (node = 0; node < NCONFIG; node = node + 1) begin
            #1 cfg_we = 1'b1;
            cfg_addr = config_mem[node][32 +: `STRAND_REG_ADDR_BITS];
            cfg_data = config_mem[node][W-1:0];
            @(posedge clk);
        end
        #1 cfg_we = 1'b0;
        cycles = 0;
        while (phase != 3'd0 || cycles == 0) begin
            @(posedge clk);
            cycles = cycles + 1;
            if (cycles > N + 4) fail("the setup did not end");
        end

        for (frame = 0; frame < FRAMES; frame = frame + 1) begin
            #1 mouse_down = mouse_mem[4 * frame][0];
            mouse_x = mouse_mem[4 * frame + 1][W-1:0];
            mouse_y = mouse_mem[4 * frame + 2][W-1:0];
            mouse_z = mouse_mem[4 * frame + 3][W-1:0];
            step = 1'b1;
            @(posedge clk);
            #1 step = 1'b0;
            cycles = 1;
            fv_n = 0;
            fec_n = 0;
            fec_first = 0;
            sig = 32'h811c9dc5;
            sample_status(cycles);
            while (!frame_done) begin
                @(posedge clk);
                #1 cycles = cycles + 1;
                sample_status(cycles);
                if (cycles > TIMEOUT) begin
                    $display("FAIL tb_top_frames: frame %0d did not finish in %0d cycles", frame, TIMEOUT);
                    $fatal(1);
                end
            end
            if (cycles != `STRAND_CYCLES_PER_FRAME) begin
                $display("FAIL tb_top_frames: frame %0d took %0d cycles, the formula says %0d", frame, cycles,
                         `STRAND_CYCLES_PER_FRAME);
                $fatal(1);
            end
            if (fv_n !== status_mem[4 * frame] || fec_n !== status_mem[4 * frame + 1]) begin
                $display("FAIL tb_top_frames: frame %0d: FV high %0d cycles, FEC high %0d; the cycle model says %0d and %0d",
                         frame + 1, fv_n, fec_n, status_mem[4 * frame], status_mem[4 * frame + 1]);
                $fatal(1);
            end
            if (fec_first !== status_mem[4 * frame + 2]) begin
                $display("FAIL tb_top_frames: frame %0d: FEC first high in cycle %0d of the frame; the cycle model says %0d",
                         frame + 1, fec_first, status_mem[4 * frame + 2]);
                $fatal(1);
            end
            if (sig !== status_mem[4 * frame + 3]) begin
                $display("FAIL tb_top_frames: frame %0d: the status (phase, FV, FEC, busy, irq, frame_done, uidx, nidx, counter) differs from the cycle model's in some cycle (signature %h, model %h)",
                         frame + 1, sig, status_mem[4 * frame + 3]);
                $fatal(1);
            end
            // read every node back: address in, data two cycles later
            for (node = 0; node < N; node = node + 1) begin
                rd_addr = ((node / K) << IW) | (node % K);
                @(posedge clk);
                @(posedge clk);
                #1;
                want_x = expect_mem[3 * (frame * N + node)][W-1:0];
                want_y = expect_mem[3 * (frame * N + node) + 1][W-1:0];
                want_z = `STRAND_DIM == 3 ? expect_mem[3 * (frame * N + node) + 2][W-1:0] : {W{1'b0}};
                if (rd_x !== want_x || rd_y !== want_y || rd_z !== want_z) begin
                    $display("FAIL tb_top_frames: frame %0d node %0d: rtl (%h, %h, %h) model (%h, %h, %h)", frame + 1, node,
                             rd_x, rd_y, rd_z, want_x, want_y, want_z);
                    $fatal(1);
                end
            end
        end
        $display("PASS tb_top_frames (%0d frames x %0d nodes bit-exact, %0d cycles per frame, FV, FEC and the status of every cycle as the cycle model says)",
                 FRAMES, N, `STRAND_CYCLES_PER_FRAME);
        $finish;
    end
endmodule

`resetall
