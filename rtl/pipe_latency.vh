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

// fx_along_pipe (the normalised distance datapath, MANTISSA > 0): 21 stages whatever MB.
function integer along_pipe_latency(input integer mb);
    along_pipe_latency = 21 + 0 * mb;
endfunction

// The distance and spring pipes (each module's header counts its stages; model/timing.c
// hw_toward_pipe_latency and hw_spring_pipe_latency): an operation on the inputs in
// cycle 0 has its result in cycle LATENCY.
function integer toward_pipe_latency(input integer sqrt_bits, input integer div_bits, input integer steps,
                                     input integer mantissa);
    toward_pipe_latency = mantissa > 0 ? along_pipe_latency(mantissa) + 3
                                       : sqrt_pipe_latency(sqrt_bits, steps) + div_pipe_latency(div_bits, steps) + 11;
endfunction

function integer toward_prev_pipe_latency(input integer sqrt_bits, input integer div_bits, input integer steps,
                                          input integer mantissa);
    toward_prev_pipe_latency = mantissa > 0 ? along_pipe_latency(mantissa) + sqrt_pipe_latency(sqrt_bits, steps) + 23
                                            : 2 * sqrt_pipe_latency(sqrt_bits, steps) + div_pipe_latency(div_bits, steps) + 28;
endfunction

function integer spring_pipe_latency(input integer sqrt_bits, input integer div_bits, input integer steps,
                                     input integer mantissa);
    spring_pipe_latency = mantissa > 0 ? along_pipe_latency(mantissa) + 15
                                       : sqrt_pipe_latency(sqrt_bits, steps) + div_pipe_latency(div_bits, steps) + 20;
endfunction

