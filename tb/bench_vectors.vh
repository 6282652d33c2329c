// bench_vectors.vh - what the unit benches (tb/tb_fx_*.v, tb/tb_toward*.v, tb/tb_spring_force*.v)
// do alike, included in a bench's module body after it declares name, file, n, mem [0:MAXN-1]
// and MAXN: reading the plusargs and the vectors, and the bench's one closing line.

// +name=NAME (default_name without it), +vectors=FILE, +n=COUNT; the vectors into mem. FAIL and
// $fatal on a missing argument or a file with fewer than COUNT records.
task load_vectors;
    input [8*64-1:0] default_name;
    begin
        if (!$value$plusargs("name=%s", name)) name = default_name;
        if (!$value$plusargs("vectors=%s", file) || !$value$plusargs("n=%d", n) || n < 1 || n > MAXN) begin
            $display("FAIL %0s: need +vectors=FILE and +n=1..%0d", name, MAXN);
            $fatal(1, "bad arguments");
        end
        $readmemh(file, mem, 0, n - 1);
        if (^mem[n - 1] === 1'bx) begin
            $display("FAIL %0s: vector file %0s has fewer than %0d records", name, file, n);
            $fatal(1, "short vector file");
        end
    end
endtask

// +latency=L into latency_out (the unit's latency from model/timing.c: tb/unit_latency.c or
// tb/gen_vectors.c), lo <= L <= hi.
task load_latency;
    output integer latency_out;
    input integer  lo, hi;
    begin
        latency_out = 0;
        if (!$value$plusargs("latency=%d", latency_out) || latency_out < lo || latency_out > hi) begin
            $display("FAIL %0s: need +latency=%0d..%0d", name, lo, hi);
            $fatal(1, "bad arguments");
        end
    end
endtask

// The bench's one line: "FAIL NAME: what" and $fatal when failures != 0, else
// "PASS NAME (N vectors<pass_note>)" and $finish.
task finish_bench;
    input integer       failures;
    input [8*600-1:0]   what;
    input [8*96-1:0]    pass_note;
    begin
        if (failures != 0) begin
            $display("FAIL %0s: %0s", name, what);
            $fatal(1, "mismatch");
        end
        $display("PASS %0s (%0d vectors%0s)", name, n, pass_note);
        $finish;
    end
endtask
