// stream_props - the red/black order of rtl/chain_stream.v (a wrapper top; toward_pipe is
// tb/formal/stub_toward_pipe.v: its latency and tags, any data). Run by
// tb/formal/stream.sby.
//
// A pass is two sweeps, colour 0 (even nodes, or links (2j, 2j+1)) then colour 1; uidx is
// the sweep's colour, counter the slots issued (0 .. NS, NS = K/2 + 1), FEC every slot
// issued. Every unit reads a pair of neighbouring nodes a cycle (one from each bank: node
// 2 row_e and node 2 row_o + 1) and writes up to two (write ports 1 and 2). A sweep's
// writes land from LT + 3 cycles after its start, into the next sweep when the sweeps
// overlap (the last sweep of the pass runs until they have landed). Checked:
//   - counter only holds, steps up by one, or goes back to 0 when a sweep starts (the
//     colour changes, or a start); FEC is high exactly when counter = NS, and it is
//     reached before every sweep's end;
//   - no node is written twice within SP cycles (a sweep's period), nor by both ports
//     at once: the constraints in flight together share no node; the two writes of a
//     unit in one cycle go to different banks (an even and an odd node);
//   - a write that lands in the first LT + 3 cycles of a sweep is the previous sweep's:
//     never in the first sweep of a pass, and never to a node the current sweep has read
//     already (the hazard between colours: every read follows the write it needs);
//   - centred rule: every write is to a node of its sweep's colour (each constraint
//     writes its own node and reads only the other colour), and only by port 1;
//     pairwise: the chain's end nodes are written only by the sweep of their one link's
//     colour;
//   - every address (the pair reads' rows, the writes) is in its unit (rows < ceil(K/2),
//     nodes < K); nidx is the upward units' row while the units read;
//   - done comes only after a start, after exactly 2 ITER sweeps;
//   - after a reset: done, the write enables, counter are 0.
`default_nettype none

module stream_props #(
    parameter integer W    = 8,
    parameter integer F    = 4,
    parameter integer M    = 2,
    parameter integer K    = 2,
    parameter integer ITER = 1,
    parameter [0:0]   RULE = 1'b0,
    parameter integer STEPS = 1      // the pipes' PIPE_STEPS: the stub's latency follows it
) (
    input wire               clk,
    input wire               reset,
    input wire               start,
    input wire [W-1:0]       rest_len,
    input wire [M*2*W-1:0]   pos_e_all,
    input wire [M*2*W-1:0]   pos_o_all,
    input wire [M-1:0]       pin_e_all,
    input wire [M-1:0]       pin_o_all
);
    localparam integer N  = M * K;
    localparam integer UW = M > 1 ? $clog2(M) : 1;
    localparam integer IW = K > 1 ? $clog2(K) : 1;
    localparam integer CW = $clog2(N + 1);
    localparam integer NS = K / 2 + 1;                          // slots a sweep
    localparam integer PJ = (K + 1) / 2;                        // pairs read a sweep
    localparam integer SLOTS = NS;
`include "pipe_latency.vh"
    localparam integer LT = toward_pipe_latency(1, 1, STEPS, 0);   // the stub's latency (SQRT_BITS = DIV_BITS = 1)
    localparam integer SP = NS + 1 > LT + 4 ? NS + 1 : LT + 4;  // chain_stream's sweep period

    wire             done, fec, pair_re;
    wire [M*IW-1:0]  row_e_all, row_o_all;
    wire [IW-1:0]    nidx;
    wire [M-1:0]     wr_en, wr2_en;
    wire [M*IW-1:0]  wr_idx_all, wr2_idx_all;
    wire [M*2*W-1:0] wr_pos_all, wr2_pos_all;
    wire [UW-1:0]    uidx;
    wire [CW-1:0]    counter;

    chain_stream #(.W(W), .F(F), .M(M), .K(K), .SQRT_BITS(1), .DIV_BITS(1), .ITER(ITER), .DIM(2), .RULE(RULE),
                   .ARCH(1'b1), .PIPE_STEPS(STEPS)) dut (
        .clk(clk), .reset(reset), .start(start), .done(done), .rest_len(rest_len),
        .pair_re(pair_re), .pair_row_e_all(row_e_all), .pair_row_o_all(row_o_all),
        .pair_pos_e_all(pos_e_all), .pair_pos_o_all(pos_o_all),
        .pair_prev_e_all({(M*2*W){1'b0}}), .pair_prev_o_all({(M*2*W){1'b0}}),
        .pair_pin_e_all(pin_e_all), .pair_pin_o_all(pin_o_all),
        .wr_en(wr_en), .wr_idx_all(wr_idx_all), .wr_pos_all(wr_pos_all),
        .wr2_en(wr2_en), .wr2_idx_all(wr2_idx_all), .wr2_pos_all(wr2_pos_all),
        .uidx(uidx), .nidx(nidx), .counter(counter), .fec(fec));

    reg f_init = 1'b1;
    always @(posedge clk) f_init <= 1'b0;
    always @* if (f_init) assume (reset);

    reg running;
    always @(posedge clk) running <= reset ? 1'b0 : (running ? !done : start);
    always @* if (running) assume (!start);

    reg          reset_prev, colour_prev, fec_seen;
    reg [CW-1:0] counter_prev;
    reg [15:0]   sweeps, tsw;          // sweeps of this pass so far, cycles since this sweep began
    reg [N-1:0]  read_now, read_seen;  // nodes read by the pair reads (now, and in this sweep before)
    reg [7:0]    since [0:N-1];        // cycles since each node's last write (saturating)
    reg [N-1:0]  ever;                 // written since the reset
    wire         colour   = uidx[0];
    wire         started  = start && !running;
    wire         newsweep = !reset_prev && colour != colour_prev;
    wire         step     = {1'b0, counter} == {1'b0, counter_prev} + 1'b1;
    wire [15:0]  t_now    = newsweep ? 16'd1 : tsw;  // chain_stream's t
    wire         early    = t_now < LT + 3;             // a write now is the previous sweep's

    // this cycle's reads and writes, as node bitmaps, and the checks on them
    reg [N-1:0]  wr_now;
    reg          wr_twice, wr_soon, wr_colour_bad, wr_end_bad, wr_range_bad, wr_after_read, wr_first;
    reg          rd_range_bad, wr_same_bank;
    integer u, v, p, idx;
    always @* begin
        wr_now = {N{1'b0}};
        read_now = {N{1'b0}};
        wr_twice = 1'b0;
        wr_soon = 1'b0;
        wr_colour_bad = 1'b0;
        wr_end_bad = 1'b0;
        wr_range_bad = 1'b0;
        wr_after_read = 1'b0;
        wr_first = 1'b0;
        rd_range_bad = 1'b0;
        wr_same_bank = 1'b0;
        for (u = 0; u < M; u = u + 1) if (pair_re) begin
            if (row_e_all[u*IW +: IW] >= PJ || row_o_all[u*IW +: IW] >= PJ) rd_range_bad = 1'b1;
            if (2 * row_e_all[u*IW +: IW] < K) read_now[u*K + 2 * row_e_all[u*IW +: IW]] = 1'b1;
            if (2 * row_o_all[u*IW +: IW] + 1 < K) read_now[u*K + 2 * row_o_all[u*IW +: IW] + 1] = 1'b1;
        end
        for (u = 0; u < M; u = u + 1)
            if (wr_en[u] && wr2_en[u] && wr_idx_all[u*IW] == wr2_idx_all[u*IW]) wr_same_bank = 1'b1;
        for (p = 0; p < 2 * M; p = p + 1) if (p < M ? wr_en[p] : wr2_en[p - M]) begin
            u = p < M ? p : p - M;
            idx = p < M ? wr_idx_all[u*IW +: IW] : wr2_idx_all[u*IW +: IW];
            if (idx >= K) wr_range_bad = 1'b1;
            else begin
                v = u * K + idx;
                if (wr_now[v]) wr_twice = 1'b1;
                wr_now[v] = 1'b1;
                if (ever[v] && since[v] < SP - 1) wr_soon = 1'b1;
                // (sweeps and read_seen are this sweep's from the cycle after its first)
                if (early && sweeps == 0 && !newsweep) wr_first = 1'b1;
                if (early && (read_now[v] || (read_seen[v] && !newsweep))) wr_after_read = 1'b1;
                // the colour of the sweep that issued it: the previous one while early
                if ((v % 2) != (early ? !colour : colour)) wr_colour_bad = 1'b1;
                // pairwise: the chain's end nodes are each on one link, (0, 1) of colour 0 and
                // (N-2, N-1) of colour (N-2) mod 2, so only that sweep writes them
                if (v == 0 && (early ? !colour : colour) != 1'b0) wr_end_bad = 1'b1;
                if (v == N - 1 && (early ? !colour : colour) != ((N - 2) % 2)) wr_end_bad = 1'b1;
            end
        end
    end
    always @(posedge clk) begin
        reset_prev   <= reset;
        colour_prev  <= colour;
        counter_prev <= counter;
        // FEC reached by a slot of this sweep (the count restarts at a sweep's first slot)
        if (reset || newsweep || started) fec_seen <= 1'b0;
        else if (fec && step) fec_seen <= 1'b1;
        if (reset || started) sweeps <= 16'd0;
        else if (newsweep || done) sweeps <= sweeps + 16'd1;
        // t = 1 is the cycle after a start, and the cycle the colour changes
        if (reset || started) tsw <= 16'd1;
        else if (newsweep) tsw <= 16'd2;
        else tsw <= tsw + 16'd1;
        if (reset || started || newsweep) read_seen <= {N{1'b0}};
        else read_seen <= read_seen | read_now;
        for (u = 0; u < N; u = u + 1) since[u] <= wr_now[u] ? 8'd0 : since[u] == 8'hff ? 8'hff : since[u] + 8'd1;
        if (reset) ever <= {N{1'b0}};
        else ever <= ever | wr_now;
    end

    always @* if (!f_init) begin
        if (reset_prev) begin
            assert (!done && wr_en == {M{1'b0}} && wr2_en == {M{1'b0}} && counter == 0);
        end else begin
            assert (counter <= SLOTS);
            assert (fec == (counter == SLOTS));
            assert (counter == counter_prev || step || counter == 0 || (counter == 1 && counter_prev == SLOTS));
            if (counter == 0 && counter_prev != 0) assert (counter_prev == SLOTS);
            // every slot of the sweep issued (its last may issue in its last cycle: FEC now)
            if (newsweep) assert (fec_seen || (fec && step));
            assert (!wr_twice && !wr_range_bad && !rd_range_bad && !wr_same_bank);
            assert (!wr_soon);
            assert (!wr_first);
            assert (!wr_after_read);
            assert ((wr_en == {M{1'b0}} && wr2_en == {M{1'b0}}) || running);
            if (RULE == 1'b0) assert (!wr_colour_bad && wr2_en == {M{1'b0}});
            else assert (!wr_end_bad);
            assert (nidx == (pair_re ? row_e_all[0 +: IW] : {IW{1'b0}}));
            if (done) assert (running && fec_seen && sweeps + 16'd1 == 2 * ITER);
        end
        cover (done);
    end
    wire unused = &{1'b0, wr_pos_all, wr2_pos_all};
endmodule

`resetall
