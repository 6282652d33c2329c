`default_nettype none
`timescale 1ns / 1ps

/*
 * pair_sequencer - a pass over the links of a chain of M x K nodes: the pairwise
 * constraint pass (references 001 struts, 002; SPRING = 0) or the spring force pass
 * (references 001, 004; SPRING = 1).
 *
 * SPRING = 1: for each link, model/engine_body.h spring_edge(): the spring_force
 * datapath gives the force F on a (-F on b) from both ends' positions and previous
 * positions; the ends' gathered forces become acc_a + F and acc_b - F (saturating),
 * written through the units' force port (wr_* carry the force); pins do not matter
 * (pinned nodes ignore their force); a zero length writes nothing. Each link then
 * takes LS + 5 cycles, LS = SQRT_BITS + 2 DIV_BITS + 15. The rest of this header
 * describes SPRING = 0.
 *
 * Walks the links (a, b) = (i, i+1), i = 0 .. N-2, in order, ITER times, and for
 * each computes model/engine_body.h pair_edge(): the excess e = d - d * rest/|d|
 * along d = b - a (the `toward` datapath in excess mode); both ends free: h = e/2
 * (fx_avg with 0: rounded ties-to-even), a += h, b -= h, so the midpoint stays bit
 * for bit; one end pinned: the other takes all of e; both pinned, or a zero length:
 * nothing is written. uidx/nidx are a's address, counter the links finished, and
 * FEC = (counter == N - 1).
 *
 * Timing, fixed whatever the data: each link takes LT + 5 cycles (read a, read b,
 * start toward, LT cycles until it is done, write a, write b), LT = SQRT_BITS +
 * DIV_BITS + 9; a pass over the N - 1 links takes (N - 1) * (LT + 5) cycles after
 * the start cycle; done is high the cycle after the last pass.
 *
 * GRAPH = 1 (graph bodies): the pass walks E edges of an edge memory instead of the
 * chain's links: edge j joins nodes a_j and b_j with rest length rest_j (rest_len is
 * not used); counter counts edges and FEC = (counter == E). The memory is loaded
 * through e_we (a, b, rest appended in order; reset empties it). Timing is the
 * same per edge: a pass takes E (LT + 5) cycles (LS + 5 for springs).
 *
 * DIM = 3 adds the z lane to every read, datapath and write.
 *
 * Storage is read through the units' synchronous port A (address now, data next
 * cycle) and written through their write port (wr_* are valid in the write cycle).
 */
module pair_sequencer #(
    parameter integer W         = 32,    // word width, bits
    parameter integer F         = 16,    // fraction bits
    parameter integer M         = 4,     // units
    parameter integer K         = 5,     // nodes per unit
    parameter integer UW        = 2,     // unit index width, >= 1
    parameter integer IW        = 3,     // node index width, >= 1
    parameter integer CW        = 5,     // counter width, holds M*K
    parameter integer ITER      = 1,     // passes per constraint phase
    parameter integer SQRT_BITS = W - 1, // root bits resolved
    parameter integer DIV_BITS  = W - 1, // quotient bits resolved
    parameter [0:0]   SPRING    = 1'b0,  // 0: pairwise constraint, 1: spring force
    parameter integer DIM       = 2,     // 2, or 3: a z lane
    parameter [0:0]   GRAPH     = 1'b0,  // 0: the chain's links, 1: an edge memory
    parameter integer E         = 1      // GRAPH: edges in the memory (>= 1)
) (
    input  wire          clk,
    input  wire          reset,      // synchronous, active high
    input  wire          start,      // one-cycle pulse: run ITER passes
    output reg           done,       // one-cycle pulse after the last pass
    input  wire [W-1:0]  rest_len,   // rest length of every link (chain)
    input  wire          e_we,       // GRAPH: append an edge to the memory
    input  wire [UW+IW-1:0] e_a,     //   its ends, {unit, node}
    input  wire [UW+IW-1:0] e_b,
    input  wire [W-1:0]  e_rest,     //   its rest length
    input  wire [W-1:0]  ks,         // SPRING: stiffness and damping, scaled (model init())
    input  wire [W-1:0]  kd,

    output reg  [UW-1:0] rd_uidx,    // storage read address (combinational)
    output reg  [IW-1:0] rd_nidx,
    input  wire [W-1:0]  rd_x,       // its data, the next cycle
    input  wire [W-1:0]  rd_y,
    input  wire [W-1:0]  rd_z,       // DIM = 3 only, as every z port
    input  wire          rd_pinned,
    input  wire [W-1:0]  rd_px,      // SPRING: previous position and gathered force
    input  wire [W-1:0]  rd_py,
    input  wire [W-1:0]  rd_accx,
    input  wire [W-1:0]  rd_accy,
    input  wire [W-1:0]  rd_pz,
    input  wire [W-1:0]  rd_accz,

    output wire          wr_en,      // write one end of the link now (SPRING: its force)
    output wire [UW-1:0] wr_uidx,
    output wire [IW-1:0] wr_nidx,
    output wire [W-1:0]  wr_x,
    output wire [W-1:0]  wr_y,
    output wire [W-1:0]  wr_z,

    output reg  [UW-1:0] uidx,       // the link's first node a: unit
    output reg  [IW-1:0] nidx,       //                          node
    output reg  [CW-1:0] counter,    // links finished in this pass
    output wire          fec         // counter == M x K - 1
);

    localparam integer N = M * K;
    localparam integer LINKS_I = GRAPH ? E : N - 1;           // links (edges) per pass
    localparam integer LAST_LINK_I = LINKS_I > 0 ? LINKS_I - 1 : 0;
    localparam integer AW = UW + IW;                          // a node address
    localparam integer EW = E > 1 ? $clog2(E) : 1;            // an edge index
    localparam integer ITW = ITER > 1 ? $clog2(ITER) : 1;
    localparam integer K_LAST_I = K - 1;
    localparam integer ITER_LAST_I = ITER - 1;
    localparam [CW-1:0]  LINKS     = LINKS_I[CW-1:0];
    localparam [CW-1:0]  LAST_LINK = LAST_LINK_I[CW-1:0];
    localparam [IW-1:0]  K_LAST    = K_LAST_I[IW-1:0];
    localparam [ITW-1:0] ITER_LAST = ITER_LAST_I[ITW-1:0];

    // Bad parameters stop elaboration: $error for Yosys (0.23 has no $fatal),
    // $fatal for the simulators (Icarus carries on after $error).
    initial begin
        if (M < 1 || K < 1 || ITER < 1 || (1 << CW) <= LINKS_I || (1 << CW) <= N || E < 1 || (DIM != 2 && DIM != 3)) begin
`ifdef SYNTHESIS
            $error("pair_sequencer: M, K, ITER must be >= 1 and CW must hold M*K (M=%0d K=%0d ITER=%0d CW=%0d) in %m", M, K, ITER, CW);
`else
            $fatal(1, "pair_sequencer: M, K, ITER must be >= 1 and CW must hold M*K (M=%0d K=%0d ITER=%0d CW=%0d) in %m", M, K, ITER, CW);
`endif
        end
    end

    localparam [2:0] S_IDLE = 3'd0, // waiting for start
                     S_RD_A = 3'd1, // a is addressed
                     S_RD_B = 3'd2, // a arrives; b is addressed
                     S_GO   = 3'd3, // b arrives; toward starts
                     S_WAIT = 3'd4, // until toward is done: the new a and b
                     S_WR_A = 3'd5, // write a
                     S_WR_B = 3'd6; // write b, next link

    function [UW+IW-1:0] next_node(input [UW-1:0] u, input [IW-1:0] n);
        next_node = n == K_LAST ? {u + 1'b1, {IW{1'b0}}} : {u, n + 1'b1};
    endfunction

    reg [2:0]     state_q, state_d;
    reg [ITW-1:0] iter_q;
    reg [W-1:0]   ax, ay, bx, by;       // the link's ends
    reg [W-1:0]   az, bz, apz, aaz, baz, naz, nbz;  // their z lane (DIM = 3)
    reg           a_pin, b_pin;
    reg [W-1:0]   apx, apy, aax, aay;   // SPRING: a's previous position and force, b's force
    reg [W-1:0]   bax, bay;
    reg [W-1:0]   nax, nay, nbx, nby;   // their new positions
    reg           wa, wb;               // which are written
    wire [UW-1:0] b_u;
    wire [IW-1:0] b_n;
    wire [AW-1:0] next_a;     // the next link's a
    wire [AW-1:0] first_a;    // the first link's a: node 0 (chain), or edge 0's a (graph)
    wire [W-1:0]  link_rest;  // this link's rest length

    // ---- the links: implied (chain) or from the edge memory (graph) ----
    generate
        if (GRAPH) begin : g_edges
            reg [AW-1:0] ea [0:E-1];
            reg [AW-1:0] eb [0:E-1];
            reg [W-1:0]  er [0:E-1];
            reg [EW:0]   fill;      // edges loaded
            integer j;
            always @(posedge clk) begin
                if (reset) begin
                    fill <= {(EW+1){1'b0}};
                    for (j = 0; j < E; j = j + 1) begin
                        ea[j] <= {AW{1'b0}};
                        eb[j] <= {AW{1'b0}};
                        er[j] <= {W{1'b0}};
                    end
                end else if (e_we && fill < E[EW:0]) begin
                    ea[fill[EW-1:0]] <= e_a;
                    eb[fill[EW-1:0]] <= e_b;
                    er[fill[EW-1:0]] <= e_rest;
                    fill <= fill + 1'b1;
                end
            end
            wire [EW-1:0] cur = counter < LINKS ? counter[EW-1:0] : {EW{1'b0}};
            wire [EW-1:0] nxt = counter + 1'b1 < LINKS ? cur + 1'b1 : {EW{1'b0}};
            assign {b_u, b_n} = eb[cur];
            assign next_a     = ea[nxt];
            assign first_a    = ea[0];
            assign link_rest  = er[cur];
            wire unused_chain = &{1'b0, rest_len};
        end else begin : g_links
            assign {b_u, b_n} = next_node(uidx, nidx);
            assign next_a     = {b_u, b_n};
            assign first_a    = {AW{1'b0}};
            assign link_rest  = rest_len;
            wire unused_graph = &{1'b0, e_we, e_a, e_b, e_rest};
        end
    endgenerate


    wire last_link = counter == LAST_LINK;
    wire last_iter = iter_q == ITER_LAST;

    // ---- the datapath ----
    wire         t_done, t_valid;
    wire [W-1:0] sum_ax, sum_ay, dif_bx, dif_by, sum_az, dif_bz;  // the new values of a and b
    generate
        if (SPRING) begin : g_spring
            // F from both ends; a's force + F, b's force - F
            wire [W-1:0] fx, fy, fz;
            /* verilator lint_off PINCONNECTEMPTY */
            // busy is not needed: the FSM waits for done; saturation is the result itself
            spring_force #(.W(W), .F(F), .SQRT_BITS(SQRT_BITS), .DIV_BITS(DIV_BITS), .DIM(DIM)) u_force (
                .clk(clk), .reset(reset), .start(state_q == S_GO),
                .a_x(ax), .a_y(ay), .a_px(apx), .a_py(apy), .a_z(az), .a_pz(apz),
                .b_x(rd_x), .b_y(rd_y), .b_px(rd_px), .b_py(rd_py),  // b arrives as the force starts
                .b_z(rd_z), .b_pz(rd_pz),
                .rest_len(link_rest), .ks(ks), .kd(kd),
                .busy(), .done(t_done), .f_x(fx), .f_y(fy), .f_z(fz), .valid(t_valid));
            fx_add #(.W(W)) u_az (.sub(1'b0), .a(aaz), .b(fz), .y(sum_az), .sat());
            fx_add #(.W(W)) u_bz (.sub(1'b1), .a(baz), .b(fz), .y(dif_bz), .sat());
            fx_add #(.W(W)) u_ax (.sub(1'b0), .a(aax), .b(fx), .y(sum_ax), .sat());
            fx_add #(.W(W)) u_ay (.sub(1'b0), .a(aay), .b(fy), .y(sum_ay), .sat());
            fx_add #(.W(W)) u_bx (.sub(1'b1), .a(bax), .b(fx), .y(dif_bx), .sat());
            fx_add #(.W(W)) u_by (.sub(1'b1), .a(bay), .b(fy), .y(dif_by), .sat());
            /* verilator lint_on PINCONNECTEMPTY */
            wire unused_pins = &{1'b0, a_pin, b_pin, bx, by, bz};
        end else begin : g_pair
            // the excess e = d - d * rest/|d|, then the split
            wire [W-1:0] ex, ey, ez;
            /* verilator lint_off PINCONNECTEMPTY */
            // busy is not needed: the FSM waits for done
            toward #(.W(W), .F(F), .SQRT_BITS(SQRT_BITS), .DIV_BITS(DIV_BITS), .DIM(DIM)) u_toward (
                .clk(clk), .reset(reset), .start(state_q == S_GO), .excess(1'b1),
                .p_x(ax), .p_y(ay), .c_x(rd_x), .c_y(rd_y), .rest_len(link_rest),  // b arrives as toward starts
                .p_z(az), .c_z(rd_z),
                .busy(), .done(t_done), .t_x(ex), .t_y(ey), .t_z(ez), .valid(t_valid));
            /* verilator lint_on PINCONNECTEMPTY */
            wire [W-1:0] hx, hy, hz;   // e / 2
            fx_avg #(.W(W)) u_hx (.a(ex), .b({W{1'b0}}), .y(hx));
            fx_avg #(.W(W)) u_hy (.a(ey), .b({W{1'b0}}), .y(hy));
            fx_avg #(.W(W)) u_hz (.a(ez), .b({W{1'b0}}), .y(hz));
            wire         both_free = !a_pin && !b_pin;
            wire [W-1:0] da_x = both_free ? hx : ex, da_y = both_free ? hy : ey;  // what a and b move by
            wire [W-1:0] da_z = both_free ? hz : ez;
            /* verilator lint_off PINCONNECTEMPTY */
            // saturation flags are not needed: the saturated value is the result
            fx_add #(.W(W)) u_ax (.sub(1'b0), .a(ax), .b(da_x), .y(sum_ax), .sat());
            fx_add #(.W(W)) u_ay (.sub(1'b0), .a(ay), .b(da_y), .y(sum_ay), .sat());
            fx_add #(.W(W)) u_bx (.sub(1'b1), .a(bx), .b(da_x), .y(dif_bx), .sat());
            fx_add #(.W(W)) u_by (.sub(1'b1), .a(by), .b(da_y), .y(dif_by), .sat());
            fx_add #(.W(W)) u_az (.sub(1'b0), .a(az), .b(da_z), .y(sum_az), .sat());
            fx_add #(.W(W)) u_bz (.sub(1'b1), .a(bz), .b(da_z), .y(dif_bz), .sat());
            /* verilator lint_on PINCONNECTEMPTY */
            wire unused_force = &{1'b0, ks, kd, apx, apy, aax, aay, bax, bay, apz, aaz, baz};
        end
    endgenerate

    // ---- storage access ----
    always @* begin
        rd_uidx = uidx;   // S_RD_A and otherwise: a
        rd_nidx = nidx;
        if (state_q == S_RD_B) begin
            rd_uidx = b_u;
            rd_nidx = b_n;
        end
    end
    assign wr_en   = (state_q == S_WR_A && wa) || (state_q == S_WR_B && wb);
    assign wr_uidx = state_q == S_WR_B ? b_u : uidx;
    assign wr_nidx = state_q == S_WR_B ? b_n : nidx;
    assign wr_x    = state_q == S_WR_B ? nbx : nax;
    assign wr_y    = state_q == S_WR_B ? nby : nay;
    assign wr_z    = DIM == 3 ? (state_q == S_WR_B ? nbz : naz) : {W{1'b0}};
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
                ax    <= rd_x;
                ay    <= rd_y;
                a_pin <= rd_pinned;
                apx   <= rd_px;
                apy   <= rd_py;
                aax   <= rd_accx;
                aay   <= rd_accy;
                az    <= DIM == 3 ? rd_z : {W{1'b0}};
                apz   <= DIM == 3 ? rd_pz : {W{1'b0}};
                aaz   <= DIM == 3 ? rd_accz : {W{1'b0}};
            end
            S_GO: begin
                bx    <= rd_x;
                by    <= rd_y;
                b_pin <= rd_pinned;
                bax   <= rd_accx;
                bay   <= rd_accy;
                bz    <= DIM == 3 ? rd_z : {W{1'b0}};
                baz   <= DIM == 3 ? rd_accz : {W{1'b0}};
            end
            S_WAIT: if (t_done) begin
                nax <= sum_ax;
                nay <= sum_ay;
                nbx <= dif_bx;
                nby <= dif_by;
                naz <= sum_az;
                nbz <= dif_bz;
                wa  <= t_valid && (SPRING || !a_pin);
                wb  <= t_valid && (SPRING || !b_pin);
            end
            default: ;
        endcase
    end

endmodule

`resetall
