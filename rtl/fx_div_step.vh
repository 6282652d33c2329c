// fx_div_step.vh - one iteration and the last step of the restoring long division,
// written once for the iterative fx_div and the pipelined fx_div_pipe (included in
// their bodies, after their localparams W, DB, NIT, LSB; fx_div.v's header has the
// algorithm).

// One iteration: {the new quotient bit, the new partial remainder}: twice = 2 acc + the next
// dividend bit, the bit is twice >= divisor (acc < divisor holds, so the new acc fits W bits).
function [W:0] div_step(input [W-1:0] acc, input xbit, input [W-1:0] divisor);
    reg [W:0]   twice;
    reg [W+1:0] diff;
    reg         ge;
    begin
        twice    = {acc, xbit};
        diff     = {1'b0, twice} - {2'b00, divisor};
        ge       = !diff[W+1];
        div_step = {ge, ge ? diff[W-1:0] : twice[W-1:0]};
    end
endfunction

// The result from the last iteration's quotient bits (the last one is the rounding
// bit): {clamped, quotient}, rounded at bit LSB and clamped to 2^(W-1)-1.
function [W:0] div_result(input [NIT-1:0] q_next, input big);
    reg [DB:0]  rounded;
    reg         clamp;
    reg [W-1:0] quot;
    begin
        rounded    = {1'b0, q_next[NIT-1:1]} + {{DB{1'b0}}, q_next[0]};
        clamp      = big | rounded[DB];
        quot       = {{(W-DB){1'b0}}, rounded[DB-1:0]} << LSB;
        div_result = {clamp, clamp ? {1'b0, {(W-1){1'b1}}} : quot};
    end
endfunction
