// fx_rsqrt_seed.vh - the seed table of fx_along_pipe's reciprocal root, as a constant
// function evaluated at elaboration (included in the module body; MB and T are its
// parameters). The same integer formula as model/fixed.c fx_rsqrt_seed:
//
// entry idx = {p, f} covers v in 2^p [1 + f/2^(T-1), 1 + (f+1)/2^(T-1)); with n = 2^p (2^T + 2f + 1)
// (its middle is n / 2^T), Z = floor(2^(2MB+T+2) / n), Y0 = (floor(sqrt(Z)) + 1) / 2, the
// nearest integer to 2^MB / sqrt(n / 2^T) but for Z's floor; C0 = Y0^3 / 2^2MB rounded
// (ties to even), at most 2^MB - 1. The word is {C0, Y0}, 2MB bits.

function [2*MB-1:0] rsqrt_seed_word(input integer idx);
    reg [63:0] ix, n, z, r, tr, y, cube, c, rem, half;
    integer    i;
    begin
        ix = {32'd0, idx};
        n  = ((64'd1 << T) + 2 * (ix % (64'd1 << (T - 1))) + 64'd1) << (ix / (64'd1 << (T - 1)));
        z = (64'd1 << (2 * MB + T + 2)) / n;
        r = 64'd0;
        for (i = 31; i >= 0; i = i - 1) begin
            tr = r | (64'd1 << i);
            if (tr * tr <= z) r = tr;
        end
        y    = (r + 64'd1) >> 1;
        cube = y * y * y;
        c    = cube >> (2 * MB);
        rem  = cube - (c << (2 * MB));
        half = 64'd1 << (2 * MB - 1);
        if (rem > half || (rem == half && c[0])) c = c + 64'd1;
        if (c > (64'd1 << MB) - 64'd1) c = (64'd1 << MB) - 64'd1;
        rsqrt_seed_word = {c[MB-1:0], y[MB-1:0]};
    end
endfunction
