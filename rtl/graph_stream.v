`default_nettype none
`timescale 1ns / 1ps

`include "strand_defs.vh"

/*
 * graph_stream - the pipelined constraint pass over a graph body (ARCH = 1, GRAPH = 1):
 * the rods and struts of the edge memory stream through one toward_pipe, colour by
 * colour, a new edge every two cycles.
 *
 * Order (model/engine_body.h with order = redblack): the edges are in the memory in
 * the order of a greedy edge colouring (scene_set_order: colour by colour, each in
 * the scene's order), and hwgen marks the last edge of each colour (the EDGE word's
 * bit 2 AW + 1). No two edges of a colour share a node, so a whole colour can be in
 * flight at once and the result is the one of taking its edges one by one; between
 * two colours the pipeline drains: the next colour's first read comes after the
 * last write of this one. That is all the hazard there is, and it costs LT + 3
 * cycles a colour.
 *
 * Why two cycles an edge: an edge reads two nodes and writes two, and the unit has
 * one read port (A) and one write port. Each is busy every cycle of a colour.
 *
 * An edge j (every unit in step; LT is the pipe's latency, model/timing.c
 * hw_toward_pipe_latency), counting its first cycle as A:
 *   A        the entry (a, b, rest, last) is on the memory's output; port A reads a
 *   A + 1    (B) a arrives; port A reads b; the memory reads the next entry
 *   A + 2    b arrives: the edge enters the pipe (excess mode, P = a, C = b, carried),
 *            and the next edge's A (within a colour)
 *   A + 2 + LT      the excess e leaves the pipe: a += e/2, b -= e/2 (one end fixed:
 *                   the other takes e; both fixed or a zero length: nothing)
 *   A + 3 + LT      a is written
 *   A + 4 + LT      b is written
 * After a colour's last edge the pass waits (S_DRAIN) until b's write; the next
 * colour's A is the cycle after. A pass over E edges in C colours takes
 * 2 E + C (LT + 3) cycles; ITER passes follow each other, and done is high the cycle
 * after the last write (the start cycle comes first: model/timing.c has the formula).
 * The last entry of the memory always ends a colour.
 *
 * The memory is filled as pair_sequencer's is (e_we appends; reset empties it; an
 * entry not filled reads as an edge from node 0 to node 0 of rest 0, a zero length,
 * with no colour mark).
 *
 * Observation (DEBUG): {uidx, nidx} the current edge's a, counter the edges read in
 * this pass, FEC = every edge of the pass read.
 */
module graph_stream #(
`include "strand_params.vh"
) (
    input  wire             clk,
    input  wire             reset,      // synchronous, active high
    input  wire             start,      // one-cycle pulse: run ITER passes
    output reg              done,       // one-cycle pulse after the last pass
    input  wire             e_we,       // append an edge to the memory
    input  wire [AW-1:0]    e_a,        //   its ends, {unit, node}
    input  wire [AW-1:0]    e_b,
    input  wire [W-1:0]     e_rest,     //   its rest length
    input  wire             e_last,     //   it is the last edge of its colour

    output reg  [AW-1:0]    rd_addr,    // port A address (combinational)
    input  wire [DIM*W-1:0] rd_pos,     // its data, the next cycle
    input  wire             rd_pinned,
    input  wire [DIM*W-1:0] rd_prev,    // PROJECTION: the previous position

    output reg              wr_en,      // write one end of an edge now
    output reg  [AW-1:0]    wr_addr,
    output reg  [DIM*W-1:0] wr_pos,

    output wire [UW-1:0]    uidx,       // observation: the current edge's a
    output wire [IW-1:0]    nidx,
    output reg  [CW-1:0]    counter,    //   edges read in this pass
    output wire             fec         //   every edge of the pass read
);

    localparam integer DW     = DIM * W;
    localparam integer E      = E_RODS;
`include "pipe_latency.vh"
    localparam integer LT     = PROJECTION ? toward_prev_pipe_latency(SQRT_BITS, DIV_BITS, PIPE_STEPS, MANTISSA)
                                           : toward_pipe_latency(SQRT_BITS, DIV_BITS, PIPE_STEPS, MANTISSA);
    localparam integer EW     = E > 1 ? $clog2(E) : 1;       // an edge index
    localparam integer ITW    = ITER > 1 ? $clog2(ITER) : 1;
    localparam integer DRW    = $clog2(LT + 3);
    localparam integer TAG_W  = 2 * AW + 2;                   // a, b, a's pin, b's pin
    localparam integer E_LAST_I = E - 1, ITER_LAST_I = ITER - 1, DRAIN_I = LT + 2;
    localparam [EW-1:0]  E_LAST    = E_LAST_I[EW-1:0];
    localparam [CW-1:0]  EDGES     = E[CW-1:0];
    localparam [ITW-1:0] ITER_LAST = ITER_LAST_I[ITW-1:0];
    localparam [DRW-1:0] DRAIN     = DRAIN_I[DRW-1:0];

    // (strand_core instantiates it for a graph only; the table's defaults, a chain, pass too)
    `STRAND_CHECK(graph_stream_build, !GRAPH || (RULE == 1 && M == 1 && (1 << CW) > E),
                  ("graph_stream: a graph (GRAPH=%0d) needs the pairwise rule (RULE=%0d), one unit (M=%0d), CW=%0d counting E=%0d in %m",
                   GRAPH, RULE, M, CW, E))

    localparam [1:0] S_IDLE  = 2'd0, // waiting for start
                     S_A     = 2'd1, // the entry is out: read a
                     S_B     = 2'd2, // a arrives: read b
                     S_DRAIN = 2'd3; // after a colour's last edge: until its last write

    reg [1:0]     state_q;
    reg [EW-1:0]  j;         // the edge whose entry is on the memory's output (S_A)
    reg [ITW-1:0] iter_q;
    reg [DRW-1:0] drain_q;
    reg [AW-1:0]  a_q, b_q;  // the edge's ends (from S_A)
    reg [W-1:0]   rest_q;
    reg           last_q;    // it ends its colour
    reg [DW-1:0]  a_pos, a_prev;
    reg           a_pin;
    reg           issue_q;   // b arrives now: the edge enters the pipe

    // ---- the edge memory: {last, rest, b, a}, read one edge ahead ----
    reg  [EW:0]          fill;       // edges loaded since reset
    reg                  entry_ok;   // the entry on the output was filled
    wire [2*AW+W:0]      entry;
    wire                 mem_re    = (state_q == S_IDLE && start) || state_q == S_B;
    wire [EW-1:0]        j_next    = j == E_LAST ? {EW{1'b0}} : j + 1'b1;
    wire [EW-1:0]        mem_raddr = state_q == S_IDLE ? {EW{1'b0}} : j_next;
    always @(posedge clk) begin
        if (reset) fill <= {(EW+1){1'b0}};
        else if (e_we && fill < E[EW:0]) fill <= fill + 1'b1;
        if (mem_re) entry_ok <= {1'b0, mem_raddr} < fill;
    end
    /* verilator lint_off PINCONNECTEMPTY */
    // one reader
    strand_ram #(.WIDTH(2 * AW + W + 1), .DEPTH(E), .ABITS(EW), .BLOCK_MIN(RAM_BLOCK_MIN), .READ_B(1'b0)) u_edges (
        .clk(clk), .we(e_we && fill < E[EW:0]), .waddr(fill[EW-1:0]), .wdata({e_last, e_rest, e_b, e_a}),
        .re_a(mem_re), .raddr_a(mem_raddr), .rdata_a(entry),
        .re_b(1'b0), .raddr_b({EW{1'b0}}), .rdata_b());
    /* verilator lint_on PINCONNECTEMPTY */
    wire [AW-1:0] ent_a    = entry_ok ? entry[AW-1:0] : {AW{1'b0}};
    wire [AW-1:0] ent_b    = entry_ok ? entry[2*AW-1:AW] : {AW{1'b0}};
    wire [W-1:0]  ent_rest = entry_ok ? entry[2*AW +: W] : {W{1'b0}};
    wire          ent_last = (entry_ok && entry[2*AW+W]) || j == E_LAST;

    wire last_iter = iter_q == ITER_LAST;
    wire drained   = state_q == S_DRAIN && drain_q == {DRW{1'b0}};
    wire pass_end  = drained && j == {EW{1'b0}};   // the drain after the memory's last edge
                                                 // (j has wrapped to 0 at its S_B)

    // ---- control ----
    always @(posedge clk) begin
        if (reset) begin
            state_q <= S_IDLE;
            j       <= {EW{1'b0}};
            iter_q  <= {ITW{1'b0}};
            drain_q <= {DRW{1'b0}};
            counter <= {CW{1'b0}};
            a_q     <= {AW{1'b0}};
            issue_q <= 1'b0;
            done    <= 1'b0;
        end else begin
            done    <= pass_end && last_iter;
            issue_q <= state_q == S_B;
            case (state_q)
                S_IDLE: if (start) begin
                    state_q <= S_A;
                    j       <= {EW{1'b0}};
                    iter_q  <= {ITW{1'b0}};
                    counter <= {CW{1'b0}};
                end
                S_A: begin
                    state_q <= S_B;
                    a_q     <= ent_a;
                end
                S_B: begin
                    counter <= counter + 1'b1;
                    j       <= j_next;
                    if (last_q) begin
                        state_q <= S_DRAIN;
                        drain_q <= DRAIN;
                    end else begin
                        state_q <= S_A;
                    end
                end
                default: begin  // S_DRAIN: LT + 3 cycles, to the colour's last write
                    drain_q <= drain_q - 1'b1;
                    if (drained) begin
                        if (pass_end && last_iter) begin
                            state_q <= S_IDLE;    // counter stays E: FEC until the next start
                        end else begin
                            state_q <= S_A;
                            if (pass_end) begin
                                iter_q  <= iter_q + 1'b1;
                                counter <= {CW{1'b0}};
                            end
                        end
                    end
                end
            endcase
        end
    end

    // ---- datapath registers, each written in its own state ----
    always @(posedge clk) begin
        if (state_q == S_A) begin
            b_q    <= ent_b;
            rest_q <= ent_rest;
            last_q <= ent_last;
        end
        if (state_q == S_B) begin
            a_pos  <= rd_pos;
            a_pin  <= rd_pinned;
            a_prev <= rd_prev;
        end
    end

    // port A: a in S_A, b in S_B
    always @* begin
        rd_addr = a_q;
        if (state_q == S_A) rd_addr = ent_a;
        if (state_q == S_B) rd_addr = b_q;
    end

    assign {uidx, nidx} = a_q;
    assign fec = counter == EDGES;

    // ---- the pipe: the edge enters the cycle b arrives (a_q, b_q, rest_q are still its own) ----
    wire             o_valid, o_ok;
    wire [DW-1:0]    o_t, o_p, o_c;
    wire [TAG_W-1:0] o_tag;
    wire [TAG_W-1:0] in_tag = {a_q, b_q, a_pin, rd_pinned};
    dist_pipe #(.W(W), .F(F), .SQRT_BITS(SQRT_BITS), .DIV_BITS(DIV_BITS), .MANTISSA(MANTISSA), .STEPS(PIPE_STEPS), .DIM(DIM), .TAG_W(TAG_W),
                .CARRY(1'b1), .PROJECTION(PROJECTION), .BLOCK_MIN(RAM_BLOCK_MIN)) u_pipe (
        .clk(clk), .reset(reset), .in_valid(issue_q), .in_excess(1'b1),
        .in_p(a_pos), .in_c(rd_pos), .in_pp(a_prev), .in_pc(rd_prev), .in_rest(rest_q), .in_tag(in_tag),
        .out_valid(o_valid), .out_t(o_t), .out_ok(o_ok), .out_tag(o_tag), .out_p(o_p), .out_c(o_c));

    // ---- the split and the two writes: a the cycle after the result, b the cycle after that ----
    wire [AW-1:0] o_a     = o_tag[TAG_W-1 -: AW];
    wire [AW-1:0] o_b     = o_tag[2 +: AW];
    wire          o_pin_a = o_tag[1];
    wire          o_pin_b = o_tag[0];
    wire          ok      = o_valid && o_ok;
    wire [DW-1:0] half, new_a, new_b;
    genvar k;
    /* verilator lint_off PINCONNECTEMPTY */
    // saturation flags: the saturated value is the result
    generate
        for (k = 0; k < DIM; k = k + 1) begin : g_lane
            fx_avg #(.W(W)) u_half (.a(o_t[k*W +: W]), .b({W{1'b0}}), .y(half[k*W +: W]));
            fx_add #(.W(W), .SUB(0)) u_a (.sub(1'b0), .a(o_p[k*W +: W]),
                                          .b(o_pin_b ? o_t[k*W +: W] : half[k*W +: W]), .y(new_a[k*W +: W]), .sat());
            fx_add #(.W(W), .SUB(1)) u_b (.sub(1'b1), .a(o_c[k*W +: W]),
                                          .b(o_pin_a ? o_t[k*W +: W] : half[k*W +: W]), .y(new_b[k*W +: W]), .sat());
        end
    endgenerate
    /* verilator lint_on PINCONNECTEMPTY */
    reg          b_en;
    reg [AW-1:0] b_addr;
    reg [DW-1:0] b_new;
    always @(posedge clk) begin
        if (o_valid) begin
            wr_addr <= o_a;
            wr_pos  <= new_a;
            b_addr  <= o_b;
            b_new   <= new_b;
        end else begin
            wr_addr <= b_addr;
            wr_pos  <= b_new;
        end
        if (reset) begin
            wr_en <= 1'b0;
            b_en  <= 1'b0;
        end else if (o_valid) begin
            wr_en <= ok && !o_pin_a;
            b_en  <= ok && !o_pin_b;
        end else begin
            wr_en <= b_en;
            b_en  <= 1'b0;
        end
    end

endmodule

`resetall
