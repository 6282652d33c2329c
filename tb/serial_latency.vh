// serial_latency.vh - the serial units' latencies, start cycle to done cycle, as the unit
// benches and the formal properties check them (tb/serial_latency_check.v): model/timing.c's
// hw_sqrt_latency, hw_div_latency, hw_toward_latency and hw_spring_latency, which
// units-latency-formulas compares these with on a grid. Included in module bodies after
// rtl/pipe_latency.vh (with a mantissa, toward and spring_force run one operation through
// their pipes).

function integer sqrt_latency(input integer bits);
    sqrt_latency = bits + 2;
endfunction

function integer div_latency(input integer bits);
    div_latency = bits + 2;
endfunction

// toward.v (toward_prev.v with projection): one operation through the pipe when mantissa > 0
function integer toward_latency(input integer sqrt_bits, input integer div_bits, input integer dim,
                                input integer steps, input integer mantissa, input integer projection);
    toward_latency = mantissa > 0 ? (projection != 0 ? toward_prev_pipe_latency(sqrt_bits, div_bits, steps, mantissa)
                                                : toward_pipe_latency(sqrt_bits, div_bits, steps, mantissa)) + 1
                   : projection != 0 ? 2 * sqrt_bits + dim * div_bits + 7 * dim + 20
                   : sqrt_latency(sqrt_bits) + div_latency(div_bits) + 2 * dim + 6;
endfunction

function integer spring_latency(input integer sqrt_bits, input integer div_bits, input integer dim,
                                input integer steps, input integer mantissa);
    spring_latency = mantissa > 0 ? spring_pipe_latency(sqrt_bits, div_bits, steps, mantissa) + 1
                                  : sqrt_bits + dim * div_bits + 5 * dim + 15;
endfunction
