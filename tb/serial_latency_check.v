`default_nettype none
`timescale 1ns / 1ps

/*
 * serial_latency_check - the latency contract of a serial unit (rtl/fx_sqrt.v, fx_div.v, toward.v,
 * toward_prev.v, spring_force.v), written once for the unit benches, which instantiate it,
 * and the formal properties, which instantiate the same module (tb/formal/*_props.sv).
 *
 * The contract: a start seen while busy is low (and reset low) is accepted; busy is high in
 * the LATENCY - 1 cycles after the accepting one and done in the cycle after those, for one
 * cycle, and at no other time; a start while busy is ignored; in the cycle after a reset,
 * busy and done are low. (The cycle in which start is high is cycle 0; done is in cycle
 * LATENCY.)
 *
 * latency is an input, so that a bench passes what model/timing.c says (+latency=, from
 * tb/unit_latency.c or tb/gen_vectors.c) and a property the task's LATENCY parameter (set by
 * scripts/formal.py from the same program); DEPTH bounds it (the history kept).
 *
 * Under FORMAL (Yosys read -formal) the contract is assumed nothing of and asserted every
 * cycle from the first reset on (the first cycle is assumed to be a reset). In simulation
 * the check runs at every rising edge on the values before it, from the first reset on;
 * violations counts the cycles that broke it and the first is printed as
 * "FAIL latency contract of <instance>: cycle N: ...", so a bench fails by its own count of
 * errors plus this one (the check cannot be skipped by a bench that forgets a condition).
 */
module serial_latency_check #(
    parameter integer DEPTH = 64   // the largest latency checked
) (
    input  wire        clk,
    input  wire        reset,
    input  wire [15:0] latency,    // start cycle to done cycle, 2 .. DEPTH
    input  wire        start,
    input  wire        busy,
    input  wire        done,
    output reg  [31:0] violations
);
    localparam [15:0] DEPTH16 = DEPTH[15:0];
    wire              accept = start && !busy && !reset;
    reg  [DEPTH-1:0]  pend;        // bit i: a start accepted i + 1 cycles ago
    reg               reset_prev;
    wire [DEPTH-1:0]  below = ~({DEPTH{1'b1}} << (latency - 16'd1)); // bits 0 .. latency - 2
    wire [DEPTH-1:0]  due  = {{(DEPTH-1){1'b0}}, 1'b1} << (latency - 16'd1);   // bit latency - 1
    wire              done_due = |(pend & due);
    wire              busy_due = |(pend & below);
    always @(posedge clk) begin
        pend       <= reset ? {DEPTH{1'b0}} : {pend[DEPTH-2:0], accept};
        reset_prev <= reset;
    end
`ifdef FORMAL
    reg f_init = 1'b1;
    always @(posedge clk) f_init <= 1'b0;
    always @* if (f_init) assume (reset);
    always @* assume (latency >= 16'd2 && latency <= DEPTH16);
    always @* if (!f_init) begin
        if (reset_prev) assert (!busy && !done);
        else begin
            assert (done == done_due);
            assert (busy == busy_due);
            assert ($onehot0(pend));
        end
        cover (done);
    end
    always @* violations = 32'd0;
`else
    reg     seen_reset;
    integer cycle;
    initial begin
        seen_reset = 1'b0;
        violations = 32'd0;
        cycle      = 0;
    end
    always @(posedge clk) begin
        if (seen_reset) begin
            cycle <= cycle + 1;
            if (latency < 16'd2 || latency > DEPTH16) begin
                if (violations == 0)
                    $display("FAIL latency contract of %m: latency %0d is outside 2..%0d", latency, DEPTH);
                violations <= violations + 1;
            end else if (reset_prev ? (busy !== 1'b0 || done !== 1'b0) : (busy !== busy_due || done !== done_due)) begin
                if (violations == 0)
                    $display("FAIL latency contract of %m: cycle %0d after the first reset: busy=%b done=%b, the contract (latency %0d) says busy=%b done=%b",
                             cycle, busy, done, latency, reset_prev ? 1'b0 : busy_due, reset_prev ? 1'b0 : done_due);
                violations <= violations + 1;
            end
        end
        if (reset) seen_reset <= 1'b1;
    end
`endif
endmodule

`resetall
