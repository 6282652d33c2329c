// pair_seq_props - the walk of rtl/pair_sequencer.v over a chain's links (SPRING = 0,
// GRAPH = 0; a wrapper top; toward is tb/formal/stub_toward.v: any latency, any result).
// Run by tb/formal/pair_seq.sby.
//
// Seen from the ports only: counter counts the links (a, b) = (i, i+1) finished in a pass,
// and a link is finished (visited) when counter steps up. Checked:
//   - counter only holds, steps up by one, or goes from L = N-1 (the pass's end) back to 0;
//     it never exceeds L; FEC is high exactly when counter = L;
//   - while FEC is low, a = (uidx, nidx) is in range and is node counter: the links are
//     taken in order; a bitmap of the links finished in the pass is full exactly when FEC
//     rises, and no link is finished twice;
//   - a write (wr_en) goes to a or b of the current link (node counter or counter + 1),
//     in range, each end at most once a link;
//   - the storage read address is always a node of the chain;
//   - done comes only after a start, with FEC high, after exactly PASSES passes;
//   - after a reset: done, wr_en, counter, uidx, nidx are 0.
// The caller starts the sequencer only when it is idle: assumed.
`default_nettype none

module pair_seq_props #(
    parameter integer W      = 8,
    parameter integer F      = 4,
    parameter integer M      = 2,
    parameter integer K      = 2,
    parameter integer PASSES = 2
) (
    input wire           clk,
    input wire           reset,
    input wire           start,
    input wire [W-1:0]   rest_len,
    input wire [2*W-1:0] rd_pos,
    input wire           rd_pinned
);
    localparam integer N  = M * K;
    localparam integer L  = N - 1;                // links of a pass
    localparam integer LB = L > 0 ? L : 1;        // bitmap width
    localparam integer UW = M > 1 ? $clog2(M) : 1;
    localparam integer IW = K > 1 ? $clog2(K) : 1;
    localparam integer AW = UW + IW;
    localparam integer CW = $clog2(N + 1);

    wire           done, wr_en, fec;
    wire [UW-1:0]  rd_uidx, wr_uidx, uidx;
    wire [IW-1:0]  rd_nidx, wr_nidx, nidx;
    wire [CW-1:0]  counter;
    wire [2*W-1:0] wr_pos;

    pair_sequencer #(.W(W), .F(F), .M(M), .K(K), .SQRT_BITS(1), .DIV_BITS(1), .DIM(2), .GRAPH(1'b0),
                     .SPRING(1'b0), .PASSES(PASSES), .E(1)) dut (
        .clk(clk), .reset(reset), .start(start), .done(done), .rest_len(rest_len),
        .e_we(1'b0), .e_a({AW{1'b0}}), .e_b({AW{1'b0}}), .e_rest({W{1'b0}}), .ks({W{1'b0}}), .kd({W{1'b0}}),
        .rd_uidx(rd_uidx), .rd_nidx(rd_nidx), .rd_pos(rd_pos), .rd_pinned(rd_pinned),
        .rd_prev({2*W{1'b0}}), .rd_acc({2*W{1'b0}}),
        .wr_en(wr_en), .wr_uidx(wr_uidx), .wr_nidx(wr_nidx), .wr_pos(wr_pos),
        .uidx(uidx), .nidx(nidx), .counter(counter), .fec(fec));

    reg f_init = 1'b1;
    always @(posedge clk) f_init <= 1'b0;
    always @* if (f_init) assume (reset);

    reg running;
    always @(posedge clk) running <= reset ? 1'b0 : (running ? !done : start);
    always @* if (running) assume (!start);

    reg          reset_prev;
    reg [CW-1:0] counter_prev;
    reg [31:0]   a_prev;
    reg [LB-1:0] seen;
    reg          wrote_a, wrote_b;
    reg [15:0]   passes;
    wire [31:0]  a_node  = uidx * K + nidx;
    wire [31:0]  w_node  = wr_uidx * K + wr_nidx;
    wire [31:0]  r_node  = rd_uidx * K + rd_nidx;
    wire         step    = !reset_prev && {1'b0, counter} == {1'b0, counter_prev} + 1'b1;
    wire         newpass = !reset_prev && counter == {CW{1'b0}} && counter_prev == L;
    wire [LB-1:0] seen_base = newpass ? {LB{1'b0}} : seen;
    wire [LB-1:0] seen_now  = step ? seen_base | ({{(LB-1){1'b0}}, 1'b1} << a_prev) : seen_base;
    wire         w_a = wr_en && w_node == a_node;
    wire         w_b = wr_en && w_node == a_node + 1;
    always @(posedge clk) begin
        reset_prev   <= reset;
        counter_prev <= counter;
        a_prev       <= a_node;
        seen         <= reset ? {LB{1'b0}} : seen_now;
        if (reset || counter != counter_prev) begin
            wrote_a <= 1'b0;
            wrote_b <= 1'b0;
        end
        if (!reset && w_a) wrote_a <= 1'b1;
        if (!reset && w_b) wrote_b <= 1'b1;
        if (reset || (start && !running)) passes <= 16'd0;
        else if (step && counter == L) passes <= passes + 16'd1;
    end

    always @* if (!f_init) begin
        if (reset_prev) begin
            assert (!done && !wr_en && counter == 0 && uidx == 0 && nidx == 0);
        end else begin
            assert (counter <= L);
            assert (fec == (counter == L));
            assert (counter == counter_prev || step || newpass);
            if (step) assert (!seen_base[a_prev]);
            if (!fec) assert (uidx < M && nidx < K && a_node == counter);
            if (L > 0) assert ((seen_now == {LB{1'b1}}) == fec);
            if (wr_en) begin
                assert (!fec && wr_nidx < K && w_node < N && (w_a || w_b));
                if (w_a) assert (!wrote_a || counter != counter_prev);
                if (w_b) assert (!wrote_b || counter != counter_prev);
            end
            assert (rd_nidx < K && r_node < N);
            if (done) assert (running && fec && passes + (step ? 16'd1 : 16'd0) == PASSES);
        end
        cover (done);
    end
endmodule

`resetall
