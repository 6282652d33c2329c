// strand_defs.vh - the one style of parameter check, for every module of rtl/.
//
//     `STRAND_CHECK(label, condition, ("module: what is wrong (X=%0d) in %m", X))
//
// stops elaboration when the condition is false: the simulators print the message
// and $fatal; Yosys 0.23 prints no $error text, so under SYNTHESIS the check is an
// instance of a module that does not exist, named `label` (say what is wrong in
// it, e.g. W_must_be_8_to_32), and `hierarchy -check` stops with that name.
`ifndef STRAND_DEFS_VH
`define STRAND_DEFS_VH

// FUSE (a chain's pipelined centred pass): the first sweep of a pass takes its words from the
// units' Verlet step instead of the memories, this many cycles later: node_unit's stages R, A,
// B and C (model/timing.c hw_fuse_lag).
`define STRAND_FUSE_LAG 4
`ifdef SYNTHESIS
`define STRAND_CHECK(label, cond, msg) generate if (!(cond)) begin : label strand_bad_parameter label (); end endgenerate
`else
`define STRAND_CHECK(label, cond, msg) initial if (!(cond)) begin $display msg; $fatal(1); end
`endif
`endif
