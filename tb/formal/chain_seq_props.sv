// chain_seq_props - the walk of rtl/chain_sequencer.v (a wrapper top; toward is
// tb/formal/stub_toward.v: any latency, any result). Run by tb/formal/chain_seq.sby.
//
// Seen from the ports only: counter counts the nodes finished in a pass, and a node is
// finished (visited) when counter steps up; C = (uidx, nidx) is then that node. Checked:
//   - counter only holds, steps up by one, or goes from N (the pass's end) back to 0;
//     it never exceeds N; FEC is high exactly when counter = N;
//   - while FEC is low, C is in range and is node counter (u K + n = counter): the walk
//     goes 0, 1, .., N-1, each node once a pass; a bitmap of the nodes finished in the
//     pass is full exactly when FEC rises, and no node is finished twice;
//   - a write (wr_en) is to C, in range, at most once per node and pass;
//   - done comes only after a start, once, with FEC high, after exactly ITER passes;
//   - the storage read address has nidx < K, and is a node of the chain except while
//     C is one of the last two nodes: then the window's look-ahead (the node after D)
//     reads one or two nodes past the end; that data is not used (has_d is 0), and
//     strand_core returns 0 for a unit index past its units;
//   - after a reset: done, wr_en, counter, uidx, nidx are 0.
// The caller (frame_ctrl) starts the sequencer only when it is idle: assumed.
`default_nettype none

module chain_seq_props #(
    parameter integer W    = 8,
    parameter integer F    = 4,
    parameter integer M    = 2,
    parameter integer K    = 2,
    parameter integer ITER = 2
) (
    input wire           clk,
    input wire           reset,
    input wire           start,
    input wire [W-1:0]   rest_len,
    input wire [2*W-1:0] rd_pos,
    input wire           rd_pinned
);
    localparam integer N  = M * K;
    localparam integer UW = M > 1 ? $clog2(M) : 1;
    localparam integer IW = K > 1 ? $clog2(K) : 1;
    localparam integer CW = $clog2(N + 1);

    wire          done, wr_en, fec;
    wire [UW-1:0] rd_uidx, wr_uidx, uidx;
    wire [IW-1:0] rd_nidx, wr_nidx, nidx;
    wire [CW-1:0] counter;
    wire [2*W-1:0] wr_pos;

    chain_sequencer #(.W(W), .F(F), .M(M), .K(K), .SQRT_BITS(1), .DIV_BITS(1), .ITER(ITER), .DIM(2)) dut (
        .clk(clk), .reset(reset), .start(start), .done(done), .rest_len(rest_len),
        .rd_uidx(rd_uidx), .rd_nidx(rd_nidx), .rd_pos(rd_pos), .rd_pinned(rd_pinned),
        .wr_en(wr_en), .wr_uidx(wr_uidx), .wr_nidx(wr_nidx), .wr_pos(wr_pos),
        .uidx(uidx), .nidx(nidx), .counter(counter), .fec(fec));

    reg f_init = 1'b1;
    always @(posedge clk) f_init <= 1'b0;
    always @* if (f_init) assume (reset);

    // the caller: a start only while the sequencer is idle
    reg running;
    always @(posedge clk) running <= reset ? 1'b0 : (running ? !done : start);
    always @* if (running) assume (!start);

    reg          reset_prev;
    reg [CW-1:0] counter_prev;
    reg [UW-1:0] uidx_prev;
    reg [IW-1:0] nidx_prev;
    reg [N-1:0]  seen, written;
    reg [15:0]   passes;
    wire [31:0]  c_node  = uidx * K + nidx;
    wire [31:0]  c_prev  = uidx_prev * K + nidx_prev;
    wire [31:0]  w_node  = wr_uidx * K + wr_nidx;
    wire         step    = !reset_prev && {1'b0, counter} == {1'b0, counter_prev} + 1'b1;
    wire         newpass = !reset_prev && counter == {CW{1'b0}} && counter_prev == N;
    always @(posedge clk) begin
        reset_prev   <= reset;
        counter_prev <= counter;
        uidx_prev    <= uidx;
        nidx_prev    <= nidx;
        seen    <= reset ? {N{1'b0}} : seen_now;
        written <= reset ? {N{1'b0}} : written_now | (wr_en ? {{(N-1){1'b0}}, 1'b1} << w_node : {N{1'b0}});
        if (reset || (start && !running)) passes <= 16'd0;
        else if (step && counter == N) passes <= passes + 16'd1;
    end
    // the nodes finished and written in this pass, up to and including this cycle
    wire [N-1:0] seen_base   = newpass ? {N{1'b0}} : seen;
    wire [N-1:0] seen_now    = step ? seen_base | ({{(N-1){1'b0}}, 1'b1} << c_prev) : seen_base;
    wire [N-1:0] written_now = newpass ? {N{1'b0}} : written;

    always @* if (!f_init) begin
        if (reset_prev) begin
            assert (!done && !wr_en && counter == 0 && uidx == 0 && nidx == 0);
        end else begin
            assert (counter <= N);
            assert (fec == (counter == N));
            assert (counter == counter_prev || step || newpass);
            if (step) assert (!seen_base[c_prev]);
            if (!fec) assert (uidx < M && nidx < K && c_node == counter);
            assert ((seen_now == {N{1'b1}}) == fec);
            if (wr_en) assert (!fec && wr_uidx == uidx && wr_nidx == nidx && !written_now[w_node]);
            if (done) assert (running && fec && passes + (step ? 16'd1 : 16'd0) == ITER);
            assert (rd_nidx < K);
            if (counter + 2 < N) assert (rd_uidx * K + rd_nidx < N);
        end
        cover (done);
    end
endmodule

`resetall
