// stream_props - the red/black order of rtl/chain_stream.v (a wrapper top; toward_pipe is
// tb/formal/stub_toward_pipe.v: its latency and tags, any data). Run by
// tb/formal/stream.sby.
//
// A pass is two sweeps, colour 0 (even nodes, or links (2j, 2j+1)) then colour 1; uidx is
// the sweep's colour, counter the slots issued (0 .. K+1), FEC every slot issued. Checked:
//   - counter only holds, steps up by one, or goes back to 0 when a sweep starts (the
//     colour changes, or a start); FEC is high exactly when counter = K+1, and it is
//     reached before every sweep's end;
//   - within a sweep no node is written twice: the constraints in flight together (a
//     sweep's writes all land after its reads, the pipe being longer than the sweep's
//     slots) share no node;
//   - centred rule: every write is to a node of the sweep's colour (each constraint
//     writes its own node and reads only the other colour); a write of a sweep cannot
//     land in the next one;
//   - every address (port A, writes) is a node of its unit (< K);
//   - done comes only after a start, after exactly 2 ITER sweeps;
//   - after a reset: done, wr_en, counter are 0.
`default_nettype none

module stream_props #(
    parameter integer W    = 8,
    parameter integer F    = 4,
    parameter integer M    = 2,
    parameter integer K    = 2,
    parameter integer ITER = 1,
    parameter [0:0]   RULE = 1'b0
) (
    input wire               clk,
    input wire               reset,
    input wire               start,
    input wire [W-1:0]       rest_len,
    input wire [M*2*W-1:0]   rd_pos_all,
    input wire [M-1:0]       rd_pin_all
);
    localparam integer N  = M * K;
    localparam integer UW = M > 1 ? $clog2(M) : 1;
    localparam integer IW = K > 1 ? $clog2(K) : 1;
    localparam integer CW = $clog2(N + 1);
    localparam integer SLOTS = K + 1;

    wire             done, fec;
    wire [IW-1:0]    rd_idx, nidx;
    wire [M-1:0]     wr_en;
    wire [M*IW-1:0]  wr_idx_all;
    wire [M*2*W-1:0] wr_pos_all;
    wire [UW-1:0]    uidx;
    wire [CW-1:0]    counter;

    chain_stream #(.W(W), .F(F), .M(M), .K(K), .SQRT_BITS(1), .DIV_BITS(1), .ITER(ITER), .DIM(2), .RULE(RULE),
                   .ARCH(1'b1)) dut (
        .clk(clk), .reset(reset), .start(start), .done(done), .rest_len(rest_len),
        .rd_idx(rd_idx), .rd_pos_all(rd_pos_all), .rd_pin_all(rd_pin_all),
        .wr_en(wr_en), .wr_idx_all(wr_idx_all), .wr_pos_all(wr_pos_all),
        .uidx(uidx), .nidx(nidx), .counter(counter), .fec(fec));

    reg f_init = 1'b1;
    always @(posedge clk) f_init <= 1'b0;
    always @* if (f_init) assume (reset);

    reg running;
    always @(posedge clk) running <= reset ? 1'b0 : (running ? !done : start);
    always @* if (running) assume (!start);

    reg          reset_prev, colour_prev, fec_seen;
    reg [CW-1:0] counter_prev;
    reg [N-1:0]  written;
    reg [15:0]   sweeps;
    wire         colour   = uidx[0];
    wire         started  = start && !running;
    wire         newsweep = !reset_prev && colour != colour_prev;
    wire         step     = {1'b0, counter} == {1'b0, counter_prev} + 1'b1;

    // this cycle's writes, as a node bitmap, and whether one repeats a node of the sweep
    reg [N-1:0]  wr_now;
    reg          wr_twice, wr_colour_bad, wr_range_bad;
    integer u;
    always @* begin
        wr_now = {N{1'b0}};
        wr_twice = 1'b0;
        wr_colour_bad = 1'b0;
        wr_range_bad = 1'b0;
        for (u = 0; u < M; u = u + 1) if (wr_en[u]) begin
            if (wr_idx_all[u*IW +: IW] >= K) wr_range_bad = 1'b1;
            else begin
                if (written[u*K + wr_idx_all[u*IW +: IW]] && !newsweep) wr_twice = 1'b1;
                if (wr_now[u*K + wr_idx_all[u*IW +: IW]]) wr_twice = 1'b1;
                wr_now[u*K + wr_idx_all[u*IW +: IW]] = 1'b1;
                if (((u * K + wr_idx_all[u*IW +: IW]) % 2) != colour) wr_colour_bad = 1'b1;
            end
        end
    end
    always @(posedge clk) begin
        reset_prev   <= reset;
        colour_prev  <= colour;
        counter_prev <= counter;
        if (reset || newsweep || started) written <= wr_now;
        else written <= written | wr_now;
        if (reset || newsweep || started) fec_seen <= fec;
        else if (fec) fec_seen <= 1'b1;
        if (reset || started) sweeps <= 16'd0;
        else if (newsweep || done) sweeps <= sweeps + 16'd1;
    end

    always @* if (!f_init) begin
        if (reset_prev) begin
            assert (!done && wr_en == {M{1'b0}} && counter == 0);
        end else begin
            assert (counter <= SLOTS);
            assert (fec == (counter == SLOTS));
            assert (counter == counter_prev || step || counter == 0);
            if (counter == 0 && counter_prev != 0) assert (newsweep || counter_prev == SLOTS);
            if (newsweep) assert (fec_seen);
            assert (!wr_twice && !wr_range_bad);
            if (RULE == 1'b0) assert (!wr_colour_bad);
            assert (rd_idx < K && nidx == rd_idx);
            if (done) assert (running && fec_seen && sweeps + 16'd1 == 2 * ITER);
        end
        cover (done);
    end
    wire unused = &{1'b0, wr_pos_all};
endmodule

`resetall
