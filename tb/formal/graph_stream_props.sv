// graph_stream_props - the colour-by-colour pass of rtl/graph_stream.v (a wrapper top;
// toward_pipe is tb/formal/stub_toward_pipe.v: its latency and tags, any data). Run by
// tb/formal/graph_stream.sby.
//
// The edges are loaded (E of them, between nodes 0 .. K-1, a != b) while the pass is idle,
// each with its colour-end mark as the solver picks them, under the one promise strand
// hwgen keeps: the edges of a colour share no node. Then any number of starts. An edge's
// two reads are its S_A and S_B cycles, the two cycles before counter steps up. Checked:
//   - the hazard: no node is read (by port A, for an edge) while an edge already read
//     still has its write of that node to come: a read of a node written at A + LT + 3
//     (a) or A + LT + 4 (b) by an edge read at A, A + 1 comes after that write, and not
//     in its cycle (the memory reads before it writes);
//   - every write is an end of an edge read LT + 3 cycles before (a) or LT + 3 cycles
//     after its b was read (b), of a node in range;
//   - counter steps up by one at most every two cycles, goes back to 0 only at a start
//     or between passes, FEC is counter = E;
//   - done only after a start, after ITER passes (E edges each), and then no write is
//     still to come;
//   - after a reset: done, wr_en, counter 0.
`default_nettype none

module graph_stream_props #(
    parameter integer W    = 8,
    parameter integer F    = 4,
    parameter integer K    = 4,
    parameter integer E    = 3,
    parameter integer ITER = 1,
    parameter integer STEPS = 1      // the pipes' PIPE_STEPS: the stub's latency follows it
) (
    input wire           clk,
    input wire           reset,
    input wire           start,
    input wire           e_we,
    input wire [1:0]     e_a,
    input wire [1:0]     e_b,
    input wire [W-1:0]   e_rest,
    input wire           e_last,
    input wire [2*W-1:0] rd_pos,
    input wire           rd_pinned
);
    localparam integer IW = K > 1 ? $clog2(K) : 1;
    localparam integer AW = 1 + IW;                       // UW = 1 (M = 1)
    localparam integer CW = $clog2((E > K ? E : K) + 1);
`include "pipe_latency.vh"
    localparam integer LT = toward_pipe_latency(1, 1, STEPS, 0); // the stub's latency (SQRT_BITS = DIV_BITS = 1)

    wire          done, fec, wr_en;
    wire [AW-1:0] rd_addr, wr_addr;
    wire [2*W-1:0] wr_pos;
    wire          uidx;
    wire [IW-1:0] nidx;
    wire [CW-1:0] counter;

    graph_stream #(.W(W), .F(F), .M(1), .K(K), .SQRT_BITS(1), .DIV_BITS(1), .ITER(ITER), .DIM(2), .RULE(1'b1),
                   .ARCH(1'b1), .GRAPH(1'b1), .E_RODS(E), .COLOURS(1), .PIPE_STEPS(STEPS)) dut (
        .clk(clk), .reset(reset), .start(start), .done(done),
        .e_we(e_we), .e_a({1'b0, e_a[IW-1:0]}), .e_b({1'b0, e_b[IW-1:0]}), .e_rest(e_rest), .e_last(e_last),
        .rd_addr(rd_addr), .rd_pos(rd_pos), .rd_pinned(rd_pinned), .rd_prev({(2*W){1'b0}}),
        .wr_en(wr_en), .wr_addr(wr_addr), .wr_pos(wr_pos),
        .uidx(uidx), .nidx(nidx), .counter(counter), .fec(fec));

    reg f_init = 1'b1;
    always @(posedge clk) f_init <= 1'b0;
    always @* if (f_init) assume (reset);

    // ---- the stimulus: E edges loaded while idle, colours that share no node, then starts ----
    reg         running;
    reg [2:0]   loaded;
    reg [K-1:0] in_colour;  // nodes of the colour being loaded
    always @(posedge clk) begin
        running <= reset ? 1'b0 : (running ? !done : start && loaded == E);
        if (reset) begin
            loaded    <= 3'd0;
            in_colour <= {K{1'b0}};
        end else if (e_we) begin
            loaded    <= loaded + 3'd1;
            in_colour <= e_last ? {K{1'b0}} : in_colour | (1 << e_a[IW-1:0]) | (1 << e_b[IW-1:0]);
        end
    end
    always @* begin
        if (running || loaded == E || reset) assume (!e_we);
        if (e_we) assume (e_a < K && e_b < K && e_a != e_b && !in_colour[e_a[IW-1:0]] && !in_colour[e_b[IW-1:0]]);
        if (running || loaded != E) assume (!start);
    end

    // ---- the reads of each edge (its S_A and S_B: the two cycles before counter steps up) ----
    reg          reset_prev;
    reg [CW-1:0] counter_prev;
    reg [AW-1:0] addr_1, addr_2;     // port A's address one and two cycles ago
    reg [15:0]   now, last_step;
    reg [15:0]   due [0:K-1];        // the cycle of a node's last write planned (0: none since the reset)
    reg [15:0]   passes;
    wire         started = start && !running;
    wire         stepped = !reset_prev && counter == counter_prev + 1'b1;
    wire [IW-1:0] ra = addr_2[IW-1:0], rb = addr_1[IW-1:0];   // the edge just read: a, b
    integer n;
    always @(posedge clk) begin
        reset_prev   <= reset;
        counter_prev <= counter;
        addr_1       <= rd_addr;
        addr_2       <= addr_1;
        now          <= reset ? 16'd1 : now + 16'd1;
        if (reset || started) last_step <= 16'd0;
        else if (stepped) last_step <= now;
        if (reset || started) passes <= 16'd0;
        else if (stepped && counter == E) passes <= passes + 16'd1;
        for (n = 0; n < K; n = n + 1)
            if (reset) due[n] <= 16'd0;
            else if (stepped && n == ra) due[n] <= now - 16'd2 + LT + 3;   // a read at now - 2
            else if (stepped && n == rb) due[n] <= now - 16'd1 + LT + 3;   // b read at now - 1
    end

    always @* if (!f_init) begin
        if (reset_prev) begin
            assert (!done && !wr_en && counter == 0);
        end else begin
            // the hazard: this edge's reads (at now - 2 and now - 1) come after every write
            // of the same nodes still to come from an edge read before
            if (stepped) begin
                assert (ra < K && rb < K && ra != rb);
                assert (due[ra] == 16'd0 || due[ra] < now - 16'd2);
                assert (due[rb] == 16'd0 || due[rb] < now - 16'd1);
            end
            // every write is one an edge read LT + 3 cycles before
            if (wr_en) assert (wr_addr < K && due[wr_addr[IW-1:0]] == now);
            assert (counter <= E && fec == (counter == E));
            assert (counter == counter_prev || stepped || counter == 0);
            if (stepped) assert (now - last_step >= 2 || last_step == 0);
            if (counter == 0 && counter_prev != 0) assert (counter_prev == E);
            assert (!wr_en || running || done);
            if (done) begin
                assert (running && passes == ITER);
                for (n = 0; n < K; n = n + 1) assert (due[n] == 16'd0 || due[n] < now);
            end
        end
        cover (done && passes == ITER);
    end
    wire unused = &{1'b0, wr_pos, uidx, nidx, addr_1[AW-1], addr_2[AW-1], e_a[1], e_b[1]};
endmodule

`resetall
