// fx_sqrt_step.vh - one iteration and the last step of the digit-by-digit square root,
// written once for the iterative fx_sqrt and the pipelined fx_sqrt_pipe (included in
// their bodies, after their localparams W, SB, NIT, LSB, AW, TW; fx_sqrt.v's header has
// the algorithm).

// One iteration: {the new root bit, the new partial remainder}: ac_in = 4 ac + the next
// two radicand bits, trial = 4 q + 1, the bit is ac_in >= trial.
function [AW:0] sqrt_step(input [AW-1:0] ac, input [1:0] xtop, input [NIT-1:0] q);
    reg [TW-1:0] ac_in, trial;
    reg [TW:0]   diff;
    reg          ge;
    begin
        ac_in     = {ac, xtop};
        trial     = {q, 2'b01};
        diff      = {1'b0, ac_in} - {1'b0, trial};
        ge        = !diff[TW];
        sqrt_step = {ge, ge ? diff[AW-1:0] : ac_in[AW-1:0]};
    end
endfunction

// The result from the last iteration's root bits (the last one is the rounding bit):
// {sat, root}, the root rounded at bit LSB and clamped to 2^(W-1)-1.
function [W:0] sqrt_result(input [NIT-1:0] q_next, input big);
    reg [SB:0]  rounded;
    reg         clamp;
    reg [W-1:0] root;
    begin
        rounded     = {1'b0, q_next[NIT-1:1]} + {{SB{1'b0}}, q_next[0]};
        clamp       = big | rounded[SB];
        root        = {{(W-SB){1'b0}}, rounded[SB-1:0]} << LSB;
        sqrt_result = {clamp, clamp ? {1'b0, {(W-1){1'b1}}} : root};
    end
endfunction
