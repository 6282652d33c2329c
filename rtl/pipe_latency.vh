// pipe_latency.vh - the latencies of the datapaths and their root and divider, written once for
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


// The serial units, start cycle to done cycle (model/timing.c hw_sqrt_latency, hw_div_latency,
// hw_toward_latency, hw_spring_latency; tb/serial_latency_check.v checks them in the unit benches
// and the formal properties, and units-latency-formulas checks these functions against timing.c).
function integer sqrt_latency(input integer bits);
    sqrt_latency = bits + 2;
endfunction

function integer div_latency(input integer bits);
    div_latency = bits + 2;
endfunction

// toward.v (toward_prev.v with projection): one operation through the pipe when mantissa > 0
function integer toward_latency(input integer sqrt_bits, input integer div_bits, input integer dim,
                                input integer steps, input integer mantissa, input integer projection);
    toward_latency = mantissa > 0 ? (projection ? toward_prev_pipe_latency(sqrt_bits, div_bits, steps, mantissa)
                                                : toward_pipe_latency(sqrt_bits, div_bits, steps, mantissa)) + 1
                   : projection ? 2 * sqrt_bits + dim * div_bits + 7 * dim + 20
                   : sqrt_latency(sqrt_bits) + div_latency(div_bits) + 2 * dim + 6;
endfunction

function integer spring_latency(input integer sqrt_bits, input integer div_bits, input integer dim,
                                input integer steps, input integer mantissa);
    spring_latency = mantissa > 0 ? spring_pipe_latency(sqrt_bits, div_bits, steps, mantissa) + 1
                                  : sqrt_bits + dim * div_bits + 5 * dim + 15;
endfunction
