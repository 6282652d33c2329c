// spring_stream_props - the pipelined spring pass of rtl/spring_stream.v (a wrapper top;
// spring_force_pipe is tb/formal/stub_spring_force_pipe.v: its latency and tags, and a
// force f(a, ap, b, bp) the checker can compute, zero length when a = b). Run by
// tb/formal/spring_stream.sby.
//
// The node memory is modelled: every node's position, previous position and force are
// any constants, and port A returns the addressed node of each unit the cycle after its
// address, as strand_ram does. Checked, with start and reset at any cycle:
//   - a start is taken only when the pass is idle (or in its done cycle); done is high
//     exactly S = K + LS + 4 cycles after the cycle that follows it, one cycle wide, and
//     never without a start (LS = spring_pipe_latency(), the pipe's latency: rtl/pipe_latency.vh);
//   - every node of the chain is written exactly once in a pass, never outside one, at an
//     address of its unit (< K); port A's address is < K and nidx follows it;
//   - the written force of node n (any one, chosen by the solver) is the chain's gather, lane by lane and saturating:
//     (acc[n] - F(n-1, n)) + F(n, n+1), with F of a missing link (before node 0, after
//     node N-1) and of a zero length 0: the links cross unit borders correctly;
//   - counter counts the slots issued, 0 .. K+1, and all K+1 were issued by the pass's end;
//   - after a reset: done, wr_en and counter are 0.
`default_nettype none

module spring_stream_props #(
    parameter integer W    = 8,
    parameter integer F    = 4,
    parameter integer M    = 2,
    parameter integer K    = 2,
    parameter integer DIM  = 2,
    parameter integer SQRT_BITS = 1,
    parameter integer DIV_BITS  = 1,
    parameter integer STEPS     = 1   // the pipes' PIPE_STEPS: the stub's latency follows it
) (
    input wire         clk,
    input wire         reset,
    input wire         start,
    input wire [W-1:0] rest_len,
    input wire [W-1:0] ks,
    input wire [W-1:0] kd
);
    localparam integer N  = M * K;
    localparam integer DW = DIM * W;
    localparam integer UW = M > 1 ? $clog2(M) : 1;
    localparam integer IW = K > 1 ? $clog2(K) : 1;
    localparam integer CW = $clog2(N + 1);
`include "pipe_latency.vh"
    localparam integer LS = spring_pipe_latency(SQRT_BITS, DIV_BITS, STEPS, 0);
    localparam integer S  = K + LS + 4;

    (* anyconst *) reg [N*DW-1:0] pos_mem, prev_mem, acc_mem;

    wire             done;
    wire [IW-1:0]    rd_idx, nidx;
    reg  [M*DW-1:0]  rd_pos_all, rd_prev_all, rd_acc_all;
    wire [M-1:0]     wr_en;
    wire [M*IW-1:0]  wr_idx_all;
    wire [M*DW-1:0]  wr_acc_all;
    wire [UW-1:0]    uidx;
    wire [CW-1:0]    counter;

    spring_stream #(.W(W), .F(F), .M(M), .K(K), .SQRT_BITS(SQRT_BITS), .DIV_BITS(DIV_BITS), .DIM(DIM),
                    .EN_SPRINGS(1'b1), .ARCH(1'b1), .PIPE_STEPS(STEPS)) dut (
        .clk(clk), .reset(reset), .start(start), .done(done), .rest_len(rest_len), .ks(ks), .kd(kd),
        .rd_idx(rd_idx), .rd_pos_all(rd_pos_all), .rd_prev_all(rd_prev_all), .rd_acc_all(rd_acc_all),
        .wr_en(wr_en), .wr_idx_all(wr_idx_all), .wr_acc_all(wr_acc_all),
        .uidx(uidx), .nidx(nidx), .counter(counter));

    // port A of every unit: the addressed node's words the cycle after
    // (reads are muxes over the nodes, not variable part-selects, which would bring x bits
    // that the abc engines refuse; an address out of range reads 0, and rd_idx < K is asserted)
    integer u, l, n;
    always @(posedge clk)
        for (u = 0; u < M; u = u + 1) begin
            rd_pos_all[u*DW +: DW]  <= {DW{1'b0}};
            rd_prev_all[u*DW +: DW] <= {DW{1'b0}};
            rd_acc_all[u*DW +: DW]  <= {DW{1'b0}};
            for (n = 0; n < K; n = n + 1) if (rd_idx == n) begin
                rd_pos_all[u*DW +: DW]  <= pos_mem[(u*K + n)*DW +: DW];
                rd_prev_all[u*DW +: DW] <= prev_mem[(u*K + n)*DW +: DW];
                rd_acc_all[u*DW +: DW]  <= acc_mem[(u*K + n)*DW +: DW];
            end
        end

    // the expected force of every node: link forces as the stub computes them, gathered
    function [W-1:0] sat_add(input [W-1:0] a, input [W-1:0] b, input sub);
        reg [W:0] s;
        begin
            s = sub ? {a[W-1], a} - {b[W-1], b} : {a[W-1], a} + {b[W-1], b};
            if (s[W] == s[W-1]) sat_add = s[W-1:0];
            else sat_add = s[W] ? {1'b1, {(W-1){1'b0}}} : {1'b0, {(W-1){1'b1}}};
        end
    endfunction
    // one node, chosen by the solver, is followed: its expected force, from the forces of
    // its two links as the stub computes them (a missing link or a zero length: 0)
    (* anyconst *) reg [7:0] watch;
    always @* assume (watch < N);
    function [DW-1:0] link_force(input integer c);   // link (c-1, c), on node c-1: 1 <= c < N
        integer j;
        begin
            link_force = {DW{1'b0}};
            if (pos_mem[(c-1)*DW +: DW] != pos_mem[c*DW +: DW])
                for (j = 0; j < DIM; j = j + 1)
                    link_force[j*W +: W] = pos_mem[(c-1)*DW + j*W +: W] - pos_mem[c*DW + j*W +: W]
                                         + (prev_mem[(c-1)*DW + j*W +: W] ^ prev_mem[c*DW + j*W +: W]);
        end
    endfunction
    reg [DW-1:0] f_left, f_right, watch_acc, expect_acc;
    always @* begin
        f_left    = {DW{1'b0}};
        f_right   = {DW{1'b0}};
        watch_acc = {DW{1'b0}};
        for (n = 0; n < N; n = n + 1) if (watch == n) begin
            if (n >= 1)    f_left  = link_force(n);
            if (n + 1 < N) f_right = link_force(n + 1);
            watch_acc = acc_mem[n*DW +: DW];
        end
        for (l = 0; l < DIM; l = l + 1)
            expect_acc[l*W +: W] = sat_add(sat_add(watch_acc[l*W +: W], f_left[l*W +: W], 1'b1), f_right[l*W +: W], 1'b0);
    end

    reg f_init = 1'b1;
    always @(posedge clk) f_init <= 1'b0;
    always @* if (f_init) assume (reset);

    // the pass as the checker sees it: since = 1 the cycle after an accepted start
    reg  [7:0]   since;
    reg          reset_prev;
    reg [N-1:0]  written;
    reg          all_slots;
    wire         accepted = start && (since == 0 || since == S + 1);
    always @(posedge clk) begin
        reset_prev <= reset;
        if (reset) since <= 8'd0;
        else if (accepted) since <= 8'd1;
        else if (since == S + 1) since <= 8'd0;
        else if (since != 0) since <= since + 8'd1;
    end

    reg [N-1:0] wr_now;
    reg         wr_twice, wr_range_bad, wr_value_bad;
    always @* begin
        wr_now = {N{1'b0}};
        wr_twice = 1'b0;
        wr_range_bad = 1'b0;
        wr_value_bad = 1'b0;
        for (u = 0; u < M; u = u + 1) if (wr_en[u]) begin
            if (wr_idx_all[u*IW +: IW] >= K) wr_range_bad = 1'b1;
            for (n = 0; n < K; n = n + 1) if (wr_idx_all[u*IW +: IW] == n) begin
                if (written[u*K + n]) wr_twice = 1'b1;
                wr_now[u*K + n] = 1'b1;
                if (u*K + n == watch && wr_acc_all[u*DW +: DW] != expect_acc) wr_value_bad = 1'b1;
            end
        end
    end
    always @(posedge clk) begin
        if (reset || accepted) written <= {N{1'b0}};
        else written <= written | wr_now;
        if (reset || accepted) all_slots <= 1'b0;
        else if (counter == K + 1) all_slots <= 1'b1;
    end

    always @* if (!f_init) begin
        if (reset_prev) begin
            assert (!done && wr_en == {M{1'b0}} && counter == 0);
        end else begin
            assert (done == (since == S + 1));
            assert (counter <= K + 1);
            assert (rd_idx < K && nidx == rd_idx && uidx == 0);
            assert (!wr_range_bad && !wr_twice && !wr_value_bad);
            if (since == 0) assert (wr_en == {M{1'b0}});
            if (done) assert (written == {N{1'b1}} && all_slots);
        end
        cover (done);
    end
endmodule

`resetall
