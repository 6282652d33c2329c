// stub_toward - a stand-in for rtl/toward.v in the sequencer proofs (tb/formal/chain_seq.sby,
// pair_seq.sby): the same ports, a done pulse any number of cycles (at least one) after
// each start, chosen by the solver, and t and valid arbitrary (loaded at done, as toward
// does). Every behaviour of the real datapath is one of these, so a property of the
// sequencer that holds with the stub holds with toward; and the walk no longer needs the
// root and the divider to be unrolled. The stub checks that it is never started while
// busy (toward ignores a start then: the sequencer would hang).
`default_nettype none

module toward #(
    parameter integer W         = 32,
    parameter integer F         = 16,
    parameter integer SQRT_BITS = W - 1,
    parameter integer DIV_BITS  = W - 1,
    parameter integer MANTISSA  = 0,
    parameter integer DIM       = 2
) (
    input  wire             clk,
    input  wire             reset,
    input  wire             start,
    input  wire             excess,
    input  wire [DIM*W-1:0] p,
    input  wire [DIM*W-1:0] c,
    input  wire [W-1:0]     rest_len,
    output wire             busy,
    output wire             done,
    output reg  [DIM*W-1:0] t,
    output reg              valid
);
    (* anyseq *) reg             fin;      // the operation in flight ends now
    (* anyseq *) reg [DIM*W-1:0] t_any;
    (* anyseq *) reg             v_any;
    reg busy_q, done_q;
    always @(posedge clk) begin
        if (reset) begin
            busy_q <= 1'b0;
            done_q <= 1'b0;
        end else begin
            done_q <= busy_q && fin;
            if (busy_q && fin) begin
                busy_q <= 1'b0;
                t      <= t_any;
                valid  <= v_any;
            end else if (start) begin
                busy_q <= 1'b1;
            end
        end
    end
    always @* if (!reset && start) assert (!busy_q);
    assign busy = busy_q;
    assign done = done_q;
    wire unused = &{1'b0, excess, p, c, rest_len};
endmodule

`resetall
