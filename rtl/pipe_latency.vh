// pipe_latency.vh - the latencies of the pipelined root and divider, written once for
// the modules that time their operands around them (included in module bodies, like
// fx_div_step.vh). model/timing.c has the same formulas for the cycle model.
//
// fx_sqrt_pipe and fx_div_pipe: a load stage, ceil((BITS + 1) / STEPS) iteration
// stages (BITS + 1 iterations, STEPS to a stage), a rounding stage; the result of the
// operands sampled at edge e is there after edge e + the latency.

function integer sqrt_pipe_latency(input integer bits, input integer steps);
    sqrt_pipe_latency = (bits + steps) / steps + 1;
endfunction

function integer div_pipe_latency(input integer bits, input integer steps);
    div_pipe_latency = (bits + steps) / steps + 1;
endfunction
