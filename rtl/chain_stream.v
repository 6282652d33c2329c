`default_nettype none
`timescale 1ns / 1ps

`include "strand_defs.vh"

/*
 * chain_stream - the pipelined constraint pass over a chain of M x K nodes (ARCH = 1):
 * every unit streams its own nodes, two a clock, through its own distance datapath,
 * one constraint a clock: a node of the centred rule (two distance pipes side by side,
 * one for each neighbour) or a link of the pairwise rule (one pipe).
 *
 * Order (red/black, model/engine_body.h with order = redblack): a pass is two sweeps,
 * the even nodes (centred rule) or the links (2j, 2j+1) (pairwise), then the odd ones.
 * Within a sweep no two constraints share a node, and every constraint reads only
 * nodes its sweep does not write (the other colour) and the node(s) it writes itself,
 * so the whole sweep can be in flight at once and the result is the one of taking its
 * constraints one by one.
 *
 * Directions: even units stream their nodes upward (0 .. K-1), odd units downward
 * (K-1 .. 0), so the two nodes of every unit border are taken at the same time: both
 * first (the border between an odd unit and the next) or both last (an even unit and
 * the next). A unit's stream position s is node s, or node K-1-s downward. Its node
 * memories are two banks (bank_ram: even and odd nodes), so it reads a pair of stream
 * positions (2j, 2j+1) a clock, one from each bank, and writes up to two a clock, one
 * to each.
 *
 * A sweep, counting its first cycle as t = 1 (every unit in step; PJ = ceil(K/2) pairs,
 * NS = floor(K/2) + 1 slots; LT is the distance pipe's latency, model/timing.c
 * hw_toward_pipe_latency):
 *   t = 1 .. PJ   the units read pair j = t-1 (pair_re, the rows of pair_row_*_all);
 *                 its words (and previous positions, and pinned-or-held flags) arrive
 *                 at t+1
 *   t = j + 2     slot j = 0 .. NS-1 takes stream positions 2j-2 .. 2j+1: 2j and 2j+1
 *                 arriving (pair j), 2j-2 and 2j-1 from the last slot (the window); at
 *                 slot 0 position -1 is the "before" neighbour's position 0 (the unit
 *                 across the stream's start, arriving now), and position K the "after"
 *                 neighbour's position K-1 (the unit across its end: arriving at slot
 *                 PJ-1 when K is odd, held from t = PJ+1 for slot PJ when K is even).
 *                 The slot issues the one constraint of the sweep's colour among:
 *      centred:  the node at position 2j or 2j-1 (which one: the unit's colour of
 *                position 0, S_PAR, against the sweep's): the point at rest from its
 *                neighbour at position p-1 ("up" pipe) and from the one at p+1 ("down"
 *                pipe), both into their pipes at once. The two results leave together;
 *                the node becomes fx_avg of both (or the one that exists) and is
 *                written the cycle after (write port 1), unless pinned or held.
 *      pairwise: the link (2j, 2j+1) or (2j-1, 2j), whichever has the sweep's colour
 *                (a link has its lower node's: the lower position upward, the higher
 *                downward): its excess e (the pipe in excess mode from the lower node a
 *                to the higher b, P and C carried along), a += e/2 and b -= e/2 (a
 *                fixed end: the other takes e; both fixed or a zero length: nothing);
 *                a (write port 1) and b (write port 2) are written in the same cycle,
 *                the cycle after the result, each if it is this unit's node. A link
 *                across a unit border is computed by both units alike, and each writes
 *                its own end.
 *   Slot j's writes land in cycle j + LT + 3. A sweep lasts t = 1 .. SP, the next one's
 *   t = 1 following its t = SP: that one's read of pair j (this one's cycle SP + j + 1)
 *   follows the last write to either of its positions (slot j + 1's, in cycle j + LT + 4)
 *   when SP >= LT + 4, and this sweep's last slot (NS-1, at t = NS + 1) has issued by its
 *   last cycle when SP >= NS + 1: SP = max(NS + 1, LT + 4), so sweeps overlap by their
 *   drain; the last sweep of the pass runs to t = SL = NS + LT + 2 (its last write lands
 *   then), and done is high the cycle after (2 ITER sweeps a pass: (2 ITER - 1) SP + SL
 *   cycles). No cycle goes by without a read: a sweep reads pair 0 in its first cycle.
 * Global node g = u K + x has colour g mod 2; the chain's end nodes have one neighbour
 * (the operation runs and its result is dropped), so every sweep takes the same time.
 *
 * FUSE (the centred rule): the pass's first sweep also takes the Verlet step. Its pair
 * reads go to the units' step (pair_fuse), whose stage W gives the nodes as the step
 * leaves them STRAND_FUSE_LAG (4) cycles later, in place of the memories' words: so its
 * slots come 4 cycles later (ts = t - 4) and it lasts SF = SP + 4. The step writes the
 * colour-1 node and both previous positions as the pair leaves stage W; this sweep writes
 * every colour-0 node but a pinned one: its result, or where the step left it (held, or
 * no target), carried in the up pipe's tag. Same results as a Verlet pass, then the sweeps.
 *
 * Observation (DEBUG): uidx is the sweep's colour, nidx the pair read (j, while the
 * units read), counter the slots issued in this sweep (0 .. NS; it keeps the last sweep's
 * count until the next sweep issues its first slot, at t = 2), FEC = every slot issued.
 */
module chain_stream #(
`include "strand_params.vh"
) (
    input  wire             clk,
    input  wire             reset,      // synchronous, active high
    input  wire             start,      // one-cycle pulse: run ITER passes
    output reg              done,       // one-cycle pulse after the last pass
    input  wire [W-1:0]     rest_len,

    output wire             pair_re,          // the units read a pair now: the even bank's
    output wire [M*IW-1:0]  pair_row_e_all,   //   row and the odd bank's, per unit
    output wire [M*IW-1:0]  pair_row_o_all,
    input  wire [M*DIM*W-1:0] pair_pos_e_all, // the cycle after, per unit: the two words,
    input  wire [M*DIM*W-1:0] pair_pos_o_all,
    input  wire [M*DIM*W-1:0] pair_prev_e_all, //  their previous positions (PROJECTION)
    input  wire [M*DIM*W-1:0] pair_prev_o_all,
    input  wire [M-1:0]     pair_pin_e_all,   //   and whether each is pinned or held
    input  wire [M-1:0]     pair_pin_o_all,
    output reg              pair_fuse,        // FUSE: the pair read now is the Verlet step's (the first sweep's)
    output reg              pair_has_o,       //   and its odd bank's node exists (not so in the last pair of an odd K)
    input  wire [M*DIM*W-1:0] pass_pos_e_all,  // FUSE: the units' Verlet step's results, STRAND_FUSE_LAG cycles
    input  wire [M*DIM*W-1:0] pass_pos_o_all,  //   after the pair read, in place of the words: the new positions,
    input  wire [M*DIM*W-1:0] pass_prev_e_all, //   previous positions (PROJECTION),
    input  wire [M*DIM*W-1:0] pass_prev_o_all,
    input  wire [M-1:0]     pass_pin_e_all,   //   pinned or held,
    input  wire [M-1:0]     pass_pin_o_all,
    input  wire [M-1:0]     pass_held_e_all,  //   and held (GRAB)
    input  wire [M-1:0]     pass_held_o_all,

    output wire [M-1:0]     wr_en,      // write port 1, per unit: the node (centred), or
    output wire [M*IW-1:0]  wr_idx_all, //   the link's lower node a (pairwise)
    output wire [M*DIM*W-1:0] wr_pos_all,
    output wire [M-1:0]     wr2_en,     // write port 2 (pairwise): the link's higher node b
    output wire [M*IW-1:0]  wr2_idx_all,
    output wire [M*DIM*W-1:0] wr2_pos_all,

    output wire [UW-1:0]    uidx,       // observation: the colour
    output wire [IW-1:0]    nidx,       //   the pair read
    output reg  [CW-1:0]    counter,    //   slots issued in this sweep
    output wire             fec         //   every slot of the sweep issued
);

    localparam integer DW     = DIM * W;
    localparam integer NB     = 2 * DW + 2;                    // a node's bundle: {held, pin, prev, pos}
`include "pipe_latency.vh"
    localparam integer LT     = PROJECTION ? toward_prev_pipe_latency(SQRT_BITS, DIV_BITS, PIPE_STEPS, MANTISSA)
                                           : toward_pipe_latency(SQRT_BITS, DIV_BITS, PIPE_STEPS, MANTISSA);
    localparam integer PJ     = (K + 1) / 2;                   // pairs read a sweep
    localparam integer NS     = K / 2 + 1;                     // slots a sweep
    localparam [0:0]   K_EVEN = K % 2 == 0;
    localparam integer SP     = NS + 1 > LT + 4 ? NS + 1 : LT + 4;  // a sweep's cycles (t = 1 .. SP) before the next
    localparam integer SL     = NS + LT + 2;                   // the last sweep's, to its last write
    // FUSE: the first sweep of a pass takes its words from the units' Verlet step, FUSE_LAG
    // cycles after their read (node_unit's stages R, A, B, C): its slots, and its length, are
    // that much later
    localparam integer LAG    = FUSE != 0 ? `STRAND_FUSE_LAG : 0;
    localparam integer SF     = SP + LAG;                      // the first sweep's cycles before the next
    localparam integer TW     = $clog2((SL > SF ? SL : SF) + 1);
    localparam integer XW     = IW + 1;                        // a slot number, 0 .. NS-1
    localparam integer PW     = IW + 2;                        // a stream position or node, -1 .. K
    localparam integer ITW    = ITER > 1 ? $clog2(ITER) : 1;
    localparam integer TAG_W  = XW + 4;                        // j, odd, exists, a's pin, b's pin (centred: 0, pin)
    // FUSE, the centred rule's up pipe: also whether the slot is the first sweep's, and the
    // node's own position (written when the sweep leaves it where the Verlet step put it)
    localparam integer TAG_U  = FUSE != 0 ? TAG_W + 1 + DW : TAG_W;
    localparam integer SP_LAST_I = SP, SL_LAST_I = SL, SF_LAST_I = SF, LAG_I = (1 << TW) + 1 - LAG, PJ_I = PJ, PJ1_I = PJ + 1, NS1_I = NS + 1;
    localparam integer ITER_LAST_I = ITER - 1, K_LAST_I = K - 1, K_HALF_I = K / 2, LAST_ODD_I = (K - 1) / 2;
    localparam [TW-1:0]  SP_LAST = SP_LAST_I[TW-1:0];
    localparam [TW-1:0]  SL_LAST = SL_LAST_I[TW-1:0];
    localparam [TW-1:0]  SF_LAST = SF_LAST_I[TW-1:0];
    localparam [TW-1:0]  TS_FIRST = LAG_I[TW-1:0];           // the slot counter in a fused sweep's first cycle: 1 - LAG
    localparam [TW-1:0]  T_PJ    = PJ_I[TW-1:0];
    localparam [TW-1:0]  T_PJ1   = PJ1_I[TW-1:0];
    localparam [TW-1:0]  T_NS1   = NS1_I[TW-1:0];
    localparam [CW-1:0]  SLOTS   = NS[CW-1:0];
    localparam [ITW-1:0] ITER_LAST = ITER_LAST_I[ITW-1:0];
    localparam [XW-1:0]  J_HALF  = K_HALF_I[XW-1:0];           // slot K/2: position 2j = K (K even)
    localparam [XW-1:0]  J_LAST_ODD = LAST_ODD_I[XW-1:0];      // slot (K-1)/2: position 2j+1 = K (K odd)
    localparam [PW-1:0]  P_K_LAST = K_LAST_I[PW-1:0];

    `STRAND_CHECK(chain_stream_CW, (1 << CW) > NS, ("chain_stream: CW=%0d cannot count NS=%0d slots in %m", CW, NS))
    // (Yosys also checks the module as read, with the table's defaults: ARCH = 0 there)
    `STRAND_CHECK(chain_stream_PAIR, ARCH == 0 || PAIR == 1, ("chain_stream: the build must have PAIR = 1 (banked node memories) in %m"))

    // ---- the sweeps ----
    reg           running;
    reg [TW-1:0]  t;
    reg           colour;
    reg [ITW-1:0] iter_q;
    reg           fused;     // FUSE: the sweep under way is the pass's first, its words the Verlet step's
    reg [TW-1:0]  ts;        // the slot counter: t, or in a fused sweep t - LAG (from 1 - LAG, mod 2^TW)
    wire          last      = colour && iter_q == ITER_LAST;  // the pass's last sweep
    // (t counts a sweep's cycles from 1: its first cycle reads pair 0, so no cycle of the pass
    // goes by without a read or a slot but those the hazards and the pipe's drain ask for)
    wire          sweep_end = running && t == (last ? SL_LAST : fused ? SF_LAST : SP_LAST);
    // The sweep counter's next value (running, t: the registers below take it). The slot's
    // flags (issued; first, last) are formed from it a cycle ahead and registered, since they
    // select every unit's pipe inputs: a compare on t would sit before that wide fan-out.
    wire          start_now    = start && !running;
    wire          pass_end     = sweep_end && last;
    wire          running_next = reset ? 1'b0 : start_now ? 1'b1 : pass_end ? 1'b0 : running;
    localparam [TW-1:0] T_ONE  = 1;
    wire [TW-1:0] t_next       = reset || pass_end ? {TW{1'b0}} : start_now || sweep_end ? T_ONE : running ? t + 1'b1 : t;
    wire          fused_next   = !reset && (start_now ? FUSE != 0 : !sweep_end && fused);
    wire [TW-1:0] ts_next      = reset || pass_end ? {TW{1'b0}} : start_now ? TS_FIRST : sweep_end ? T_ONE
                               : running ? ts + 1'b1 : ts;
    reg           slot;          // slot j = t - 2 is issued (running, 2 <= t <= NS + 1)
    // pair t - 1 is read (running, 1 <= t <= T_PJ), the pair row jr = t - 1: both registered,
    // formed a cycle ahead from t (below), so that the memories' addresses and the pinned
    // flags' multiplexers start from flip-flops, not from the sweep counter's subtract
    reg           reading;
    reg [IW-1:0]  jr;
    wire          take_after = K_EVEN && running && ts == T_PJ1; // the neighbours' last pair arrives
    localparam [TW-1:0] T_TWO = 2;
    /* verilator lint_off UNUSEDSIGNAL */
    // a slot or pair number needs the low bits only
    wire [TW-1:0] t_minus_2 = ts - T_TWO;
    // the slot number j = t - 2, as XW bits: zero-extended first, since the sweep counter can be
    // narrower than a slot number (K = 256: TW = 8 bits, XW = 9)
    wire [TW+XW-1:0] t_minus_2_wide = {{XW{1'b0}}, t_minus_2};
    /* verilator lint_on UNUSEDSIGNAL */
    wire [XW-1:0] j  = t_minus_2_wide[XW-1:0];
    // A slot's flags, for the sweep counter at tv: {issued (2 <= tv <= NS + 1), and where slot
    // j = tv - 2 stands: j = 0, position 2j = K, position 2j+1 = K}
    function [3:0] slot_flags(input [TW-1:0] tv);
        /* verilator lint_off UNUSEDSIGNAL */
        reg [TW+XW-1:0] j_wide;   // j as XW bits, zero-extended first as j is (below): the low bits are used
        /* verilator lint_on UNUSEDSIGNAL */
        begin
            j_wide     = {{XW{1'b0}}, tv - T_TWO};
            slot_flags = {tv >= T_TWO && tv <= T_NS1, j_wide[XW-1:0] == {XW{1'b0}},
                          K_EVEN && j_wide[XW-1:0] == J_HALF, !K_EVEN && j_wide[XW-1:0] == J_LAST_ODD};
        end
    endfunction
    // next cycle's flags, from t_next's three cases rather than from t_next itself: so the
    // compares run on t beside the choice of t_next, not after it
    wire [3:0] flags_next = reset || pass_end ? slot_flags({TW{1'b0}}) : start_now ? slot_flags(TS_FIRST)
                          : sweep_end ? slot_flags(T_ONE) : running ? slot_flags(ts + 1'b1) : slot_flags(ts);
    // the slots issued: the count restarts at the sweep's first slot, so that it reaches NS
    // (FEC) even when the last slot issues in the sweep's last cycle (SP = NS + 1), and FEC
    // stays high until the next sweep's first slot
    wire [CW-1:0] counter_next = !slot ? counter : ts == T_TWO ? {{(CW-1){1'b0}}, 1'b1} : counter + 1'b1;

    // next cycle's t is t + 1 while a sweep runs on, so next cycle reads pair t when t + 1 <= T_PJ;
    // after a start or a sweep's end (but the pass's last) next cycle is a sweep's t = 1: pair 0
    wire first_read   = start_now || (sweep_end && !last);
    wire reading_next = first_read || (running && !sweep_end && t < T_PJ);
    /* verilator lint_off UNUSEDSIGNAL */
    // the row is t's low bits: zero-extended first, since the sweep counter can be narrower
    // than a row (a slot-bound unit at a short pipe)
    wire [TW+IW-1:0] t_wide = {{IW{1'b0}}, t};
    /* verilator lint_on UNUSEDSIGNAL */
    // next cycle's reading and jr (the units' row registers take them too, below)
    wire          read_d = !reset && reading_next;
    wire [IW-1:0] jr_d   = read_d && !first_read ? t_wide[IW-1:0] : {IW{1'b0}};
    localparam integer PJ_LAST_I = PJ - 1;
    localparam [IW-1:0] PJ_LAST = PJ_LAST_I[IW-1:0];
    always @(posedge clk) begin
        reading    <= read_d;
        jr         <= jr_d;
        pair_fuse  <= read_d && fused_next;
        pair_has_o <= K_EVEN || jr_d != PJ_LAST;
    end

    always @(posedge clk) begin
        running <= running_next;
        t       <= t_next;
        fused   <= fused_next;
        ts      <= ts_next;
        if (reset) begin
            colour  <= 1'b0;
            iter_q  <= {ITW{1'b0}};
            done    <= 1'b0;
            counter <= {CW{1'b0}};
        end else begin
            done <= pass_end;
            if (start_now) begin
                colour  <= 1'b0;
                iter_q  <= {ITW{1'b0}};
                counter <= {CW{1'b0}};
            end else if (sweep_end) begin
                counter <= counter_next;
                colour <= !colour;
                if (colour) iter_q <= iter_q + 1'b1;
            end else if (running) begin
                counter <= counter_next;
            end
        end
    end

    assign pair_re = reading;
    assign uidx = {{(UW-1){1'b0}}, colour};
    assign nidx = jr;
    assign fec  = counter == SLOTS;

    // where slot j stands at the stream's ends: registered from next cycle's flags (above)
    reg at_first;       // j = 0
    reg at_last_even;   // position 2j is K: no own node there
    reg at_last_odd;    // position 2j+1 is K
    always @(posedge clk) begin
        slot         <= running_next && flags_next[3];
        at_first     <= flags_next[2];
        at_last_even <= flags_next[1];
        at_last_odd  <= flags_next[0];
    end

    // The pipes' first stage is here (their IN_REG = 0): a slot's words are registered as
    // the memories give them, before any choice among them, so that a block RAM's output
    // feeds a flip-flop; the choices are made in the next cycle from these copies (_s) of
    // the slot's flags, colour, number and the rest length.
    // The window too is kept from these copies, a cycle after the slot (slot_s): so no
    // choice sits between a memory's output and a register.
    reg           slot_s, at_first_s, at_last_even_s, at_last_odd_s, colour_s, fused_s;
    reg [XW-1:0]  j_s;
    reg [W-1:0]   rest_s;
    always @(posedge clk) begin
        {slot_s, at_first_s, at_last_even_s, at_last_odd_s, colour_s, fused_s} <= {slot, at_first, at_last_even, at_last_odd, colour, fused};
        j_s    <= j;
        rest_s <= rest_len;
    end

    // ---- every unit's arrivals: stream positions 2j (arr0) and 2j+1 (arr1), as bundles ----
    wire [M*NB-1:0] arr0_all, arr1_all;
    genvar u;
    generate
        for (u = 0; u < M; u = u + 1) begin : g_rows
            localparam [0:0] DOWN = u % 2 == 1;
            // the words of the memories (held: 0, a held node is pinned to these sweeps), or in a
            // fused sweep the Verlet step's (its own copy of `fused` per unit: a wide select)
            wire [NB-1:0] mem_e = {1'b0, pair_pin_e_all[u], pair_prev_e_all[u*DW +: DW], pair_pos_e_all[u*DW +: DW]};
            wire [NB-1:0] mem_o = {1'b0, pair_pin_o_all[u], pair_prev_o_all[u*DW +: DW], pair_pos_o_all[u*DW +: DW]};
            wire [NB-1:0] own_e, own_o;
            if (FUSE != 0) begin : g_fuse_words
                wire [NB-1:0] pass_e = {pass_held_e_all[u], pass_pin_e_all[u], pass_prev_e_all[u*DW +: DW], pass_pos_e_all[u*DW +: DW]};
                wire [NB-1:0] pass_o = {pass_held_o_all[u], pass_pin_o_all[u], pass_prev_o_all[u*DW +: DW], pass_pos_o_all[u*DW +: DW]};
                reg fused_u;  // keep on the process: on the reg it would not stop the merge
                (* keep *) always @(posedge clk) fused_u <= fused_next;
                assign own_e = fused_u ? pass_e : mem_e;
                assign own_o = fused_u ? pass_o : mem_o;
            end else begin : g_mem_words
                assign own_e = mem_e;
                assign own_o = mem_o;
                wire unused_pass = &{1'b0, pass_pos_e_all[u*DW +: DW], pass_pos_o_all[u*DW +: DW], pass_prev_e_all[u*DW +: DW],
                                     pass_prev_o_all[u*DW +: DW], pass_pin_e_all[u], pass_pin_o_all[u], pass_held_e_all[u], pass_held_o_all[u]};
            end
            // The unit's rows: its own registers, formed from next cycle's read (jr_d) and kept
            // apart from every other unit's (keep: Yosys would merge equal flip-flops), so that
            // the row reaches the unit's memories and its pinned flags' K-way select from a
            // flip-flop beside them, not from one register fanned out across the device.
            reg [IW-1:0] row_e_q, row_o_q;
            assign pair_row_e_all[u*IW +: IW] = row_e_q;
            assign pair_row_o_all[u*IW +: IW] = row_o_q;
            if (!DOWN) begin : g_up          // positions 2j, 2j+1: nodes 2j (even), 2j+1 (odd), row j
                (* keep *) always @(posedge clk) begin
                    row_e_q <= jr_d;
                    row_o_q <= jr_d;
                end
                assign arr0_all[u*NB +: NB] = own_e;
                assign arr1_all[u*NB +: NB] = own_o;
            end else if (K_EVEN) begin : g_down_even  // nodes K-1-2j (odd), K-2-2j (even), row K/2-1-j
                localparam integer TOP_I = K / 2 - 1;
                localparam [IW-1:0] TOP = TOP_I[IW-1:0];
                wire [IW-1:0] row_d = read_d ? TOP - jr_d : {IW{1'b0}};
                (* keep *) always @(posedge clk) begin
                    row_e_q <= row_d;
                    row_o_q <= row_d;
                end
                assign arr0_all[u*NB +: NB] = own_o;
                assign arr1_all[u*NB +: NB] = own_e;
            end else begin : g_down_odd      // nodes K-1-2j (even, row (K-1)/2-j), K-2-2j (odd, row (K-3)/2-j)
                localparam integer TOP_E_I = (K - 1) / 2, TOP_O_I = K >= 3 ? (K - 3) / 2 : 0;
                localparam [IW-1:0] TOP_E = TOP_E_I[IW-1:0], TOP_O = TOP_O_I[IW-1:0];
                // the last pair has no odd node (K-2-2j = -1): row 0, its word unused
                (* keep *) always @(posedge clk) begin
                    row_e_q <= read_d ? TOP_E - jr_d : {IW{1'b0}};
                    row_o_q <= read_d && K >= 3 && jr_d <= TOP_O ? TOP_O - jr_d : {IW{1'b0}};
                end
                assign arr0_all[u*NB +: NB] = own_e;
                assign arr1_all[u*NB +: NB] = own_o;
            end
        end
    endgenerate

    // ---- the units ----
    generate
        for (u = 0; u < M; u = u + 1) begin : g_unit
            localparam [0:0] DOWN  = u % 2 == 1;       // the unit streams K-1 .. 0
            // colour of stream position 0: node 0, or node K-1 downward
            localparam integer S_PAR_I = (u * K + (u % 2 == 1 ? K - 1 : 0)) % 2;
            localparam [0:0] S_PAR = S_PAR_I[0:0];
            // the neighbours across the stream's start and end (upward: u-1 and u+1)
            localparam integer BEFORE_U = u % 2 == 1 ? u + 1 : u - 1;
            localparam integer AFTER_U  = u % 2 == 1 ? u - 1 : u + 1;
            localparam [0:0] HAS_BEFORE = BEFORE_U >= 0 && BEFORE_U < M;
            localparam [0:0] HAS_AFTER  = AFTER_U >= 0 && AFTER_U < M;
            localparam integer BEFORE_I = HAS_BEFORE ? BEFORE_U : u;  // (an index in range)
            localparam integer AFTER_I  = HAS_AFTER ? AFTER_U : u;

            // position -1 (slot 0) and position K (the last slot)
            wire [NB-1:0] nb_before = HAS_BEFORE ? arr0_all[BEFORE_I*NB +: NB] : {NB{1'b0}};
            wire [NB-1:0] nb_after;
            if (K_EVEN) begin : g_after_held   // the neighbour's position K-1 is its last pair's second
                reg [NB-1:0] after_q;
                always @(posedge clk) if (take_after) after_q <= HAS_AFTER ? arr1_all[AFTER_I*NB +: NB] : {NB{1'b0}};
                assign nb_after = after_q;
            end else begin : g_after_live      // ... its last pair's first, arriving with ours
                assign nb_after = HAS_AFTER ? arr0_all[AFTER_I*NB +: NB] : {NB{1'b0}};
                wire unused_take = &{1'b0, take_after};
            end

            // the slot's positions a cycle after it issues, from the registered copies
            reg  [NB-1:0] arr0_s, arr1_s, before_s, after_s;
            always @(posedge clk) begin
                arr0_s   <= arr0_all[u*NB +: NB];
                arr1_s   <= arr1_all[u*NB +: NB];
                before_s <= nb_before;
                after_s  <= nb_after;
            end
            // the window (position 2j-1; the centred rule also keeps 2j-2): the previous
            // slot's positions, kept as each slot's copies are chosen (slot_s)
            reg  [NB-1:0] w1_s;
            wire [NB-1:0] s_m1 = at_first_s ? before_s : w1_s;                       // 2j-1
            wire [NB-1:0] s_0  = at_last_even_s ? after_s : arr0_s;                  // 2j
            wire [NB-1:0] s_1  = at_last_odd_s ? after_s : arr1_s;                   // 2j+1
            always @(posedge clk) if (slot_s) w1_s <= s_1;

            wire [PW-1:0] j_p = {1'b0, j};  // slot number as a position-wide value
            wire [XW-1:0] o_j;              // the result's slot and its parity (position 2j - odd)
            wire          o_odd;
            /* verilator lint_off UNUSEDSIGNAL */
            // a node index needs the low bits only (the positions written are 0 .. K-1)
            wire [PW-1:0] o_j_p   = {1'b0, o_j};
            wire [PW-1:0] o_pos   = (o_j_p << 1) - {{(PW-1){1'b0}}, o_odd};   // 2j - odd
            wire [PW-1:0] o_pos1  = o_pos + 1'b1;
            wire [PW-1:0] o_node  = DOWN ? P_K_LAST - o_pos : o_pos;          // the node at position 2j - odd
            wire [PW-1:0] o_node1 = DOWN ? P_K_LAST - o_pos1 : o_pos1;        //   and at the one after it
            /* verilator lint_on UNUSEDSIGNAL */
            wire unused_j = &{1'b0, j_p};

            reg           wr_en_q, wr2_en_q;
            reg [IW-1:0]  wr_idx_q, wr2_idx_q;
            reg [DW-1:0]  wr_pos_q, wr2_pos_q;
            genvar k;
            if (RULE == 0) begin : g_centred
                reg  [NB-1:0] w0_s;
                always @(posedge clk) if (slot_s) w0_s <= s_0;
                wire [NB-1:0] s_m2 = w0_s;                                         // 2j-2
                // the node at p = 2j (its colour is position 0's) or p = 2j-1, and its neighbours
                // (valid in the slot's cycle; the rest a cycle later, from the copies)
                wire          even_p  = S_PAR == colour;
                wire          valid   = slot && (even_p ? !at_last_even : !at_first);
                wire          even_s  = S_PAR == colour_s;
                wire [NB-1:0] node    = even_s ? s_0  : s_m1;
                wire [NB-1:0] nb_up   = even_s ? s_m1 : s_m2;   // position p-1
                wire [NB-1:0] nb_dn   = even_s ? s_1  : s_0;    // position p+1
                wire          up_ex   = !(even_s && at_first_s && !HAS_BEFORE);
                wire          dn_ex   = even_s ? !(at_last_odd_s && !HAS_AFTER) : !(at_last_even_s && !HAS_AFTER);
                wire          pin     = node[NB-2];   // pinned or held
                wire          held    = node[NB-1];   // held, in a fused sweep
                wire             u_valid, u_ok, d_valid, d_ok;
                wire [DW-1:0]    u_t, d_t;
                wire [TAG_U-1:0] u_tag;
                wire [TAG_W-1:0] d_tag;
                // the up pipe's tag: {j, odd, exists, held, pin}; FUSE: then whether the slot is the
                // fused sweep's, and first the node's position
                wire [TAG_U-1:0] u_tag_in;
                if (FUSE != 0) begin : g_tag_fuse
                    assign u_tag_in = {node[0 +: DW], j_s, !even_s, up_ex, held, pin, fused_s};
                end else begin : g_tag
                    assign u_tag_in = {j_s, !even_s, up_ex, held, pin};
                    wire unused_fused = &{1'b0, fused_s};
                end
                /* verilator lint_off PINCONNECTEMPTY */
                // the centred rule's points: nothing is carried
                dist_pipe #(.W(W), .F(F), .SQRT_BITS(SQRT_BITS), .DIV_BITS(DIV_BITS), .MANTISSA(MANTISSA), .STEPS(PIPE_STEPS), .DIM(DIM), .TAG_W(TAG_U),
                            .PROJECTION(PROJECTION), .IN_REG(1'b0), .BLOCK_MIN(RAM_BLOCK_MIN)) u_up (
                    .clk(clk), .reset(reset), .in_valid(valid), .in_excess(1'b0),
                    .in_p(nb_up[0 +: DW]), .in_c(node[0 +: DW]), .in_pp(nb_up[DW +: DW]), .in_pc(node[DW +: DW]),
                    .in_rest(rest_s), .in_tag(u_tag_in),
                    .out_valid(u_valid), .out_t(u_t), .out_ok(u_ok), .out_tag(u_tag), .out_p(), .out_c());
                dist_pipe #(.W(W), .F(F), .SQRT_BITS(SQRT_BITS), .DIV_BITS(DIV_BITS), .MANTISSA(MANTISSA), .STEPS(PIPE_STEPS), .DIM(DIM), .TAG_W(TAG_W),
                            .PROJECTION(PROJECTION), .IN_REG(1'b0), .BLOCK_MIN(RAM_BLOCK_MIN)) u_down (
                    .clk(clk), .reset(reset), .in_valid(valid), .in_excess(1'b0),
                    .in_p(nb_dn[0 +: DW]), .in_c(node[0 +: DW]), .in_pp(nb_dn[DW +: DW]), .in_pc(node[DW +: DW]),
                    .in_rest(rest_s), .in_tag({j_s, !even_s, dn_ex, 1'b0, pin}),
                    .out_valid(d_valid), .out_t(d_t), .out_ok(d_ok), .out_tag(d_tag), .out_p(), .out_c());
                /* verilator lint_on PINCONNECTEMPTY */
                // the up pipe's tag, as it went in (FUSE: above its lowest bit, the fused flag)
                localparam integer FIELDS_AT = FUSE != 0 ? 1 : 0;
                wire [TAG_W-1:0] u_fields = u_tag[FIELDS_AT +: TAG_W];
                assign o_j   = u_fields[TAG_W-1 -: XW];
                assign o_odd = u_fields[3];
                wire up_ok = u_valid && u_ok && u_fields[2];
                wire dn_ok = d_valid && d_ok && d_tag[2];
                wire o_held = u_fields[1];
                wire o_pin  = u_fields[0];
                // FUSE: a node of the fused sweep is written unless pinned (and not held): the
                // Verlet step did not write it, so its result, or where the step put it (its
                // position, carried in the tag) when no target moves it or it is held
                wire          o_fused;
                wire [DW-1:0] o_own;
                if (FUSE != 0) begin : g_own
                    assign o_fused = u_tag[0];
                    assign o_own   = u_tag[TAG_U-1 -: DW];
                end else begin : g_no_own
                    assign o_fused = 1'b0;
                    assign o_own   = {DW{1'b0}};
                end
                wire [DW-1:0] avg;
                for (k = 0; k < DIM; k = k + 1) begin : g_lane
                    fx_avg #(.W(W)) u_avg (.a(u_t[k*W +: W]), .b(d_t[k*W +: W]), .y(avg[k*W +: W]));
                end
                wire moved = (up_ok || dn_ok) && !o_pin;
                always @(posedge clk) begin
                    wr_idx_q <= o_node[IW-1:0];
                    wr_pos_q <= o_fused && !moved ? o_own : up_ok && dn_ok ? avg : up_ok ? u_t : d_t;
                    if (reset) wr_en_q <= 1'b0;
                    else wr_en_q <= u_valid && (o_fused ? !o_pin || o_held : moved);
                    wr2_en_q  <= 1'b0;
                    wr2_idx_q <= {IW{1'b0}};
                    wr2_pos_q <= {DW{1'b0}};
                end
                // the neighbours' pins do not matter to the centred rule; the down pipe's tag repeats the up one's
                wire unused_c = &{1'b0, nb_up[NB-1:NB-2], nb_dn[NB-1:NB-2], d_tag[TAG_W-1:3], d_tag[1:0], o_node1};
            end else begin : g_pairwise
                // the link (2j, 2j+1) or (2j-1, 2j): its lower node a and higher b
                // (valid in the slot's cycle; the rest a cycle later, from the copies)
                // the colour of the link at position 0 (a unit streaming downward: its lower node's)
                localparam [0:0] LINK_PAR = DOWN ? !S_PAR : S_PAR;
                wire          even_q = LINK_PAR == colour;
                wire          valid  = slot && (even_q ? !at_last_even : 1'b1);
                wire          even_s = LINK_PAR == colour_s;
                wire [NB-1:0] lo     = even_s ? s_0 : s_m1;     // position q
                wire [NB-1:0] hi     = even_s ? s_1 : s_0;      // position q+1
                wire [NB-1:0] a      = DOWN ? hi : lo;
                wire [NB-1:0] b      = DOWN ? lo : hi;
                wire          exists = even_s ? !(at_last_odd_s && !HAS_AFTER)
                                              : !(at_first_s && !HAS_BEFORE) && !(at_last_even_s && !HAS_AFTER);
                wire             o_valid, o_ok;
                wire [DW-1:0]    o_t, o_p, o_c;
                wire [TAG_W-1:0] o_tag;
                dist_pipe #(.W(W), .F(F), .SQRT_BITS(SQRT_BITS), .DIV_BITS(DIV_BITS), .MANTISSA(MANTISSA), .STEPS(PIPE_STEPS), .DIM(DIM), .TAG_W(TAG_W),
                            .CARRY(1'b1), .PROJECTION(PROJECTION), .IN_REG(1'b0), .BLOCK_MIN(RAM_BLOCK_MIN)) u_pipe (
                    .clk(clk), .reset(reset), .in_valid(valid), .in_excess(1'b1),
                    .in_p(a[0 +: DW]), .in_c(b[0 +: DW]), .in_pp(a[DW +: DW]), .in_pc(b[DW +: DW]),
                    .in_rest(rest_s), .in_tag({j_s, !even_s, exists, a[NB-2], b[NB-2]}),
                    .out_valid(o_valid), .out_t(o_t), .out_ok(o_ok), .out_tag(o_tag), .out_p(o_p), .out_c(o_c));
                assign o_j   = o_tag[TAG_W-1 -: XW];
                assign o_odd = o_tag[3];
                wire unused_held = &{1'b0, a[NB-1], b[NB-1], fused_s};  // no fused sweep: nothing held is written
                wire o_pin_a = o_tag[1];
                wire o_pin_b = o_tag[0];
                wire ok = o_valid && o_ok && o_tag[2];
                // which ends are this unit's: position q = 2j - odd from 0, q + 1 up to K-1
                wire lo_ours = !(o_odd && o_j == {XW{1'b0}});
                wire hi_ours = o_odd ? !(K_EVEN && o_j == J_HALF) : !(!K_EVEN && o_j == J_LAST_ODD);
                wire [DW-1:0] half, new_a, new_b;
                /* verilator lint_off PINCONNECTEMPTY */
                // saturation flags: the saturated value is the result
                for (k = 0; k < DIM; k = k + 1) begin : g_lane
                    fx_avg #(.W(W)) u_half (.a(o_t[k*W +: W]), .b({W{1'b0}}), .y(half[k*W +: W]));
                    fx_add #(.W(W), .SUB(0)) u_a (.sub(1'b0), .a(o_p[k*W +: W]),
                                                  .b(o_pin_b ? o_t[k*W +: W] : half[k*W +: W]), .y(new_a[k*W +: W]), .sat());
                    fx_add #(.W(W), .SUB(1)) u_b (.sub(1'b1), .a(o_c[k*W +: W]),
                                                  .b(o_pin_a ? o_t[k*W +: W] : half[k*W +: W]), .y(new_b[k*W +: W]), .sat());
                end
                /* verilator lint_on PINCONNECTEMPTY */
                always @(posedge clk) begin
                    // a is at position q upward, q + 1 downward
                    wr_idx_q  <= DOWN ? o_node1[IW-1:0] : o_node[IW-1:0];
                    wr_pos_q  <= new_a;
                    wr2_idx_q <= DOWN ? o_node[IW-1:0] : o_node1[IW-1:0];
                    wr2_pos_q <= new_b;
                    if (reset) begin
                        wr_en_q  <= 1'b0;
                        wr2_en_q <= 1'b0;
                    end else begin
                        wr_en_q  <= ok && !o_pin_a && (DOWN ? hi_ours : lo_ours);
                        wr2_en_q <= ok && !o_pin_b && (DOWN ? lo_ours : hi_ours);
                    end
                end
            end
            assign wr_en[u]  = wr_en_q;
            assign wr2_en[u] = wr2_en_q;
            assign wr_idx_all[u*IW +: IW]  = wr_idx_q;
            assign wr2_idx_all[u*IW +: IW] = wr2_idx_q;
            assign wr_pos_all[u*DW +: DW]  = wr_pos_q;
            assign wr2_pos_all[u*DW +: DW] = wr2_pos_q;
        end
    endgenerate

endmodule

`resetall
