`default_nettype none
`timescale 1ns / 1ps

/*
 * latency_formulas - the latency functions of rtl/pipe_latency.vh and tb/serial_latency.vh over a
 * grid of configurations,
 * one line each: "UNIT W SQRT_BITS DIV_BITS DIM STEPS MANTISSA PROJECTION" and the function's
 * latency (the words tb/unit_latency.c reads, which computes the same from model/timing.c).
 * units-latency-formulas compares the two outputs line for line: the Verilog formulas the RTL,
 * its unit benches and its formal properties use against the model's, one source of truth
 * checked rather than two kept equal by hand.
 */
module latency_formulas;
`include "pipe_latency.vh"
`include "serial_latency.vh"
    integer sb, db, dim, steps, mb, proj, i, j;
    integer sbs [0:4];
    integer dbs [0:3];
    integer mbs [0:2];
    initial begin
        sbs[0] = 1; sbs[1] = 3; sbs[2] = 7; sbs[3] = 16; sbs[4] = 31;
        dbs[0] = 1; dbs[1] = 4; dbs[2] = 9; dbs[3] = 31;
        mbs[0] = 0; mbs[1] = 8; mbs[2] = 17;
        for (i = 0; i < 5; i = i + 1)
            for (j = 0; j < 4; j = j + 1)
                for (dim = 2; dim <= 3; dim = dim + 1)
                    for (steps = 1; steps <= 4; steps = steps + 1)
                        for (mb = 0; mb < 3; mb = mb + 1)
                            for (proj = 0; proj <= 1; proj = proj + 1) begin
                                sb = sbs[i];
                                db = dbs[j];
                                $display("sqrt 32 %0d %0d %0d %0d %0d %0d %0d", sb, db, dim, steps, mbs[mb], proj, sqrt_latency(sb));
                                $display("div 32 %0d %0d %0d %0d %0d %0d %0d", sb, db, dim, steps, mbs[mb], proj, div_latency(db));
                                $display("toward 32 %0d %0d %0d %0d %0d %0d %0d", sb, db, dim, steps, mbs[mb], proj,
                                         toward_latency(sb, db, dim, steps, mbs[mb], proj));
                                $display("toward_pipe 32 %0d %0d %0d %0d %0d %0d %0d", sb, db, dim, steps, mbs[mb], proj,
                                         proj ? toward_prev_pipe_latency(sb, db, steps, mbs[mb])
                                              : toward_pipe_latency(sb, db, steps, mbs[mb]));
                                $display("spring 32 %0d %0d %0d %0d %0d %0d %0d", sb, db, dim, steps, mbs[mb], proj,
                                         spring_latency(sb, db, dim, steps, mbs[mb]));
                                $display("spring_pipe 32 %0d %0d %0d %0d %0d %0d %0d", sb, db, dim, steps, mbs[mb], proj,
                                         spring_pipe_latency(sb, db, steps, mbs[mb]));
                            end
        $finish;
    end
endmodule

`resetall
