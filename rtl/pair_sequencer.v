`default_nettype none
`timescale 1ns / 1ps

`include "strand_defs.vh"

/*
 * pair_sequencer - a pass over the links of a chain of M x K nodes, or the edges
 * of a graph: the pairwise constraint pass (references 001 struts, 002; SPRING = 0)
 * or the spring force pass (references 001, 004; SPRING = 1).
 *
 * SPRING = 1: for each link, model/engine_body.h spring_edge(): the spring_force
 * datapath gives the force F on a (-F on b) from both ends' positions and previous
 * positions; the ends' gathered forces become acc_a + F and acc_b - F (saturating),
 * written through the units' force port (wr_pos carries the force); pins do not
 * matter (pinned nodes ignore their force); a zero length writes nothing. Each link
 * then takes LS + 5 cycles, LS = spring_force's latency. The rest of this header
 * describes SPRING = 0.
 *
 * Walks the links (a, b) = (i, i+1), i = 0 .. N-2, in order, PASSES times, and for
 * each computes model/engine_body.h pair_edge(): the excess e = d - d * rest/|d|
 * along d = b - a (the `toward` datapath in excess mode); both ends free: h = e/2
 * (fx_avg with 0: rounded ties-to-even), a += h, b -= h, so the midpoint stays bit
 * for bit; one end pinned: the other takes all of e; both pinned, or a zero length:
 * nothing is written. uidx/nidx are a's address, counter the links finished, and
 * FEC = (counter == the links of a pass).
 *
 * Timing, fixed whatever the data: each link takes LT + 5 cycles (read a, read b,
 * start toward, LT cycles until it is done, write a, write b), LT = toward's
 * latency; a pass over the N - 1 links takes (N - 1) (LT + 5) cycles after the start
 * cycle; done is high the cycle after the last pass (model/timing.c has the formula).
 *
 * GRAPH = 1 (graph bodies): the pass walks the E edges of an edge memory instead of
 * the chain's links: edge j joins nodes a_j and b_j with rest length rest_j (rest_len
 * is not used); counter counts edges and FEC = (counter == E). The memory (a
 * strand_ram, not reset) is filled through e_we, edges appended in order; reset
 * empties it (the fill count). An entry not filled since reset is an edge from node 0
 * to node 0 of rest 0: a zero length, nothing written. It is read one cycle ahead:
 * in S_RD_A the entry of this edge (b, rest; a is already in uidx/nidx), in S_GO
 * the entry of the next (its a). Timing is the same per edge: a pass takes E (LT + 5)
 * cycles (LS + 5 for springs).
 *
 * Positions are DIM lanes (lane k at bits k W +: W). Storage is read through the
 * units' synchronous port A (address now, data next cycle) and written through
 * their write port (wr_* are valid in the write cycle).
 */
module pair_sequencer #(
`include "strand_params.vh"
    ,
    parameter [0:0]   SPRING = 1'b0, // 0: pairwise constraint, 1: spring force
    parameter integer PASSES = 1,  // passes per start (the constraints: ITER; springs: 1)
    parameter integer E      = 1   // GRAPH: entries of the edge memory (>= 1)
) (
    input  wire             clk,
    input  wire             reset,      // synchronous, active high
    input  wire             start,      // one-cycle pulse: run PASSES passes
    output reg              done,       // one-cycle pulse after the last pass
    input  wire [W-1:0]     rest_len,   // rest length of every link (chain)
    input  wire             e_we,       // GRAPH: append an edge to the memory
    input  wire [AW-1:0]    e_a,        //   its ends, {unit, node}
    input  wire [AW-1:0]    e_b,
    input  wire [W-1:0]     e_rest,     //   its rest length
    input  wire [W-1:0]     ks,         // SPRING: stiffness and damping, scaled (model init())
    input  wire [W-1:0]     kd,

    output reg  [UW-1:0]    rd_uidx,    // storage read address (combinational)
    output reg  [IW-1:0]    rd_nidx,
    input  wire [DIM*W-1:0] rd_pos,     // its data, the next cycle
    input  wire             rd_pinned,
    input  wire [DIM*W-1:0] rd_prev,    // SPRING: previous position and gathered force
    input  wire [DIM*W-1:0] rd_acc,

    output wire             wr_en,      // write one end of the link now (SPRING: its force)
    output wire [UW-1:0]    wr_uidx,
    output wire [IW-1:0]    wr_nidx,
    output wire [DIM*W-1:0] wr_pos,

    output reg  [UW-1:0]    uidx,       // the link's first node a: unit
    output reg  [IW-1:0]    nidx,       //                          node
    output reg  [CW-1:0]    counter,    // links finished in this pass
    output wire             fec         // counter == the links of a pass
);

    localparam integer N           = M * K;
    localparam integer LINKS_I     = GRAPH ? E : N - 1;           // links (edges) per pass
    localparam integer LAST_LINK_I = LINKS_I > 0 ? LINKS_I - 1 : 0;
    localparam integer EW          = E > 1 ? $clog2(E) : 1;       // an edge index
    localparam integer ITW         = PASSES > 1 ? $clog2(PASSES) : 1;
    localparam integer PASS_LAST_I = PASSES - 1;
    localparam [CW-1:0]  LINKS     = LINKS_I[CW-1:0];
    localparam [CW-1:0]  LAST_LINK = LAST_LINK_I[CW-1:0];
    localparam [ITW-1:0] PASS_LAST = PASS_LAST_I[ITW-1:0];

    `STRAND_CHECK(pair_sequencer_counts, PASSES >= 1 && E >= 1 && (1 << CW) > LINKS_I,
                  ("pair_sequencer: PASSES, E must be >= 1 and CW must count the links (PASSES=%0d E=%0d CW=%0d) in %m",
                   PASSES, E, CW))

    localparam [2:0] S_IDLE = 3'd0, // waiting for start
                     S_RD_A = 3'd1, // a is addressed (GRAPH: and this edge's entry)
                     S_RD_B = 3'd2, // a arrives; b is addressed
                     S_GO   = 3'd3, // b arrives; the datapath starts (GRAPH: the next edge's entry is read)
                     S_WAIT = 3'd4, // until the datapath is done: the new a and b
                     S_WR_A = 3'd5, // write a
                     S_WR_B = 3'd6; // write b, next link

`include "strand_addr.vh"

    reg [2:0]        state_q, state_d;
    reg [ITW-1:0]    iter_q;
    reg [DIM*W-1:0]  a_pos, b_pos;        // the link's ends
    reg              a_pin, b_pin;
    reg [DIM*W-1:0]  a_prev, a_acc, b_acc; // SPRING: a's previous position and force, b's force
    reg [DIM*W-1:0]  a_new, b_new;        // what a and b become
    reg              wa, wb;              // which are written
    wire [AW-1:0]    b_addr;     // this link's b
    wire [AW-1:0]    next_a;     // the next link's a (valid in S_WR_B)
    wire [AW-1:0]    first_a;    // the first link's a: node 0 (chain), or edge 0's a (graph)
    wire [W-1:0]     link_rest;  // this link's rest length (valid from S_RD_B)
    reg  [AW-1:0]    b_addr_q;   // b, for its write

    // ---- the links: implied (chain) or from the edge memory (graph) ----
    generate
        if (GRAPH) begin : g_edges
            reg  [EW:0]    fill;      // edges loaded since reset
            reg  [AW-1:0]  first_q;   // edge 0's a (the walk starts there before any read)
            wire [EW-1:0]  cur = counter < LINKS ? counter[EW-1:0] : {EW{1'b0}};
            wire [EW-1:0]  nxt = counter + 1'b1 < LINKS ? cur + 1'b1 : {EW{1'b0}};
            wire           rd_next = state_q == S_GO;
            wire [EW-1:0]  raddr = rd_next ? nxt : cur;
            wire [2*AW+W-1:0] entry;   // {rest, b, a}
            reg            entry_ok;   // the entry read was filled
            always @(posedge clk) begin
                if (reset) begin
                    fill    <= {(EW+1){1'b0}};
                    first_q <= {AW{1'b0}};
                end else if (e_we && fill < E[EW:0]) begin
                    fill <= fill + 1'b1;
                    if (fill == {(EW+1){1'b0}}) first_q <= e_a;
                end
                if (state_q == S_RD_A || rd_next) entry_ok <= {1'b0, raddr} < fill;
            end
            /* verilator lint_off PINCONNECTEMPTY */
            // one reader
            strand_ram #(.WIDTH(2 * AW + W), .DEPTH(E), .ABITS(EW), .BLOCK_MIN(RAM_BLOCK_MIN), .READ_B(1'b0)) u_edges (
                .clk(clk), .we(e_we && fill < E[EW:0]), .waddr(fill[EW-1:0]), .wdata({e_rest, e_b, e_a}),
                .re_a(state_q == S_RD_A || rd_next), .raddr_a(raddr), .rdata_a(entry),
                .re_b(1'b0), .raddr_b({EW{1'b0}}), .rdata_b());
            /* verilator lint_on PINCONNECTEMPTY */
            assign b_addr    = entry_ok ? entry[2*AW-1:AW] : {AW{1'b0}};
            assign link_rest = entry_ok ? entry[2*AW +: W] : {W{1'b0}};
            assign next_a    = entry_ok ? entry[AW-1:0] : {AW{1'b0}};
            assign first_a   = first_q;
            wire unused_chain = &{1'b0, rest_len};
        end else begin : g_links
            assign b_addr    = next_node({uidx, nidx});
            assign next_a    = b_addr_q;
            assign first_a   = {AW{1'b0}};
            assign link_rest = rest_len;
            wire unused_graph = &{1'b0, e_we, e_a, e_b, e_rest};
        end
    endgenerate

    wire last_link = counter == LAST_LINK;
    wire last_iter = iter_q == PASS_LAST;

    // ---- the datapath ----
    wire             t_done, t_valid;
    wire [DIM*W-1:0] a_sum, b_sum;  // the new values of a and b
    genvar k;
    generate
        if (SPRING) begin : g_spring
            // F from both ends; a's force + F, b's force - F
            wire [DIM*W-1:0] force_a;
            /* verilator lint_off PINCONNECTEMPTY */
            // busy is not needed: the FSM waits for done; saturation is the result itself
            spring_force #(.W(W), .F(F), .SQRT_BITS(SQRT_BITS), .DIV_BITS(DIV_BITS), .MANTISSA(MANTISSA), .DIM(DIM)) u_force (
                .clk(clk), .reset(reset), .start(state_q == S_GO),
                .pos_a(a_pos), .prev_a(a_prev), .pos_b(rd_pos), .prev_b(rd_prev),  // b arrives as the force starts
                .rest_len(link_rest), .ks(ks), .kd(kd),
                .busy(), .done(t_done), .f(force_a), .valid(t_valid));
            for (k = 0; k < DIM; k = k + 1) begin : g_lane
                fx_add #(.W(W), .SUB(0)) u_a (.sub(1'b0), .a(a_acc[k*W +: W]), .b(force_a[k*W +: W]), .y(a_sum[k*W +: W]), .sat());
                fx_add #(.W(W), .SUB(1)) u_b (.sub(1'b1), .a(b_acc[k*W +: W]), .b(force_a[k*W +: W]), .y(b_sum[k*W +: W]), .sat());
            end
            /* verilator lint_on PINCONNECTEMPTY */
            wire unused_pins = &{1'b0, a_pin, b_pin, b_pos};
        end else begin : g_pair
            // the excess e = d - d * rest/|d|, then the split
            wire [DIM*W-1:0] excess;
            wire             both_free = !a_pin && !b_pin;
            /* verilator lint_off PINCONNECTEMPTY */
            // busy is not needed: the FSM waits for done
            if (PROJECTION) begin : g_previous
                // projection = previous: the excess along the direction at the substep's start
                toward_prev #(.W(W), .F(F), .SQRT_BITS(SQRT_BITS), .DIV_BITS(DIV_BITS), .MANTISSA(MANTISSA), .DIM(DIM)) u_toward (
                    .clk(clk), .reset(reset), .start(state_q == S_GO), .excess(1'b1),
                    .p(a_pos), .c(rd_pos), .pp(a_prev), .pc(rd_prev), .rest_len(link_rest),  // b arrives as it starts
                    .busy(), .done(t_done), .t(excess), .valid(t_valid));
            end else begin : g_current
                toward #(.W(W), .F(F), .SQRT_BITS(SQRT_BITS), .DIV_BITS(DIV_BITS), .MANTISSA(MANTISSA), .DIM(DIM)) u_toward (
                    .clk(clk), .reset(reset), .start(state_q == S_GO), .excess(1'b1),
                    .p(a_pos), .c(rd_pos), .rest_len(link_rest),  // b arrives as toward starts
                    .busy(), .done(t_done), .t(excess), .valid(t_valid));
            end
            for (k = 0; k < DIM; k = k + 1) begin : g_lane
                wire [W-1:0] e = excess[k*W +: W];
                wire [W-1:0] h;   // e / 2
                fx_avg #(.W(W)) u_h (.a(e), .b({W{1'b0}}), .y(h));
                wire [W-1:0] move = both_free ? h : e;  // what a and b move by
                // saturation flags are not needed: the saturated value is the result
                fx_add #(.W(W), .SUB(0)) u_a (.sub(1'b0), .a(a_pos[k*W +: W]), .b(move), .y(a_sum[k*W +: W]), .sat());
                fx_add #(.W(W), .SUB(1)) u_b (.sub(1'b1), .a(b_pos[k*W +: W]), .b(move), .y(b_sum[k*W +: W]), .sat());
            end
            /* verilator lint_on PINCONNECTEMPTY */
            wire unused_force = &{1'b0, ks, kd, a_prev, a_acc, b_acc, rd_prev, rd_acc};
        end
    endgenerate

    // ---- storage access ----
    always @* begin
        {rd_uidx, rd_nidx} = {uidx, nidx};   // S_RD_A and otherwise: a
        if (state_q == S_RD_B) {rd_uidx, rd_nidx} = b_addr;
    end
    assign wr_en   = (state_q == S_WR_A && wa) || (state_q == S_WR_B && wb);
    assign {wr_uidx, wr_nidx} = state_q == S_WR_B ? b_addr_q : {uidx, nidx};
    assign wr_pos  = state_q == S_WR_B ? b_new : a_new;
    assign fec     = counter == LINKS;

    // ---- next state ----
    always @* begin
        state_d = state_q;
        case (state_q)
            S_IDLE:  if (start) state_d = LINKS_I > 0 ? S_RD_A : S_IDLE;
            S_RD_A:  state_d = S_RD_B;
            S_RD_B:  state_d = S_GO;
            S_GO:    state_d = S_WAIT;
            S_WAIT:  if (t_done) state_d = S_WR_A;
            S_WR_A:  state_d = S_WR_B;
            S_WR_B:  state_d = last_link && last_iter ? S_IDLE : S_RD_A;
            default: state_d = S_IDLE;
        endcase
    end

    // ---- control registers ----
    always @(posedge clk) begin
        if (reset) begin
            state_q <= S_IDLE;
            iter_q  <= {ITW{1'b0}};
            uidx    <= {UW{1'b0}};
            nidx    <= {IW{1'b0}};
            counter <= {CW{1'b0}};
            done    <= 1'b0;
        end else begin
            state_q <= state_d;
            done    <= (state_q == S_IDLE && start && LINKS_I < 1) || (state_q == S_WR_B && last_link && last_iter);
            if (state_q == S_IDLE && start) begin
                iter_q  <= {ITW{1'b0}};
                {uidx, nidx} <= first_a;
                counter <= {CW{1'b0}};
            end
            if (state_q == S_RD_A && counter == LINKS) counter <= {CW{1'b0}};  // a new pass
            if (state_q == S_WR_B) begin
                if (last_link) begin
                    counter <= LINKS;  // FEC: until the next pass starts
                    if (!last_iter) begin
                        iter_q <= iter_q + 1'b1;
                        {uidx, nidx} <= first_a;
                    end
                end else begin
                    counter <= counter + 1'b1;
                    {uidx, nidx} <= next_a;
                end
            end
        end
    end

    // ---- datapath registers, each written in its own state ----
    always @(posedge clk) begin
        case (state_q)
            S_RD_B: begin
                a_pos    <= rd_pos;
                a_pin    <= rd_pinned;
                a_prev   <= rd_prev;
                a_acc    <= rd_acc;
                b_addr_q <= b_addr;
            end
            S_GO: begin
                b_pos <= rd_pos;
                b_pin <= rd_pinned;
                b_acc <= rd_acc;
            end
            S_WAIT: if (t_done) begin
                a_new <= a_sum;
                b_new <= b_sum;
                wa    <= t_valid && (SPRING || !a_pin);
                wb    <= t_valid && (SPRING || !b_pin);
            end
            default: ;
        endcase
    end

endmodule

`resetall
