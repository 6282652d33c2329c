#!/usr/bin/env python3
"""faults.py NAME OUTDIR - a copy of rtl/ with one planted fault, for the harness's fault checks.

    faults.py NAME OUTDIR   copy rtl/ to OUTDIR and plant fault NAME there
    faults.py --list        the faults, one per line

Planted faults never live in rtl/: each is a list of edits (file, pattern, replacement)
applied to a copy; the pattern is a regular expression (re.M) and the replacement may
use its groups. An edit whose pattern does not match exactly once stops with an error,
so a fault that no longer applies to the RTL fails loudly instead of testing nothing.
The harness (--expect-fault NAME) predicts from the cycle model the cycle at which
each must first show, and passes only if the first mismatch is there.
"""
import os
import re
import shutil
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

FAULTS = {
    # bit 0 of x flipped in the fifth pass write of unit 0 after reset: storage and the write-back lane
    "flip": [
        ("node_unit.v", r"^    wire \[DIM\*W-1:0\] wdata, wdata2;\n",
         "    wire [DIM*W-1:0] wdata, wdata2;\n"
         "    reg [2:0] fault_writes;  // planted fault: pass writes since reset\n"
         "    always @(posedge clk)\n"
         "        if (reset) fault_writes <= 3'd0;\n"
         "        else if (pass_we && fault_writes != 3'd7) fault_writes <= fault_writes + 1'b1;\n"
         "    wire fault_flip = UNIT_ID == 0 && pass_we && fault_writes == 3'd4;\n"),
        ("node_unit.v", r"\.wdata\(wdata\[k\*W \+: W\]\),",
         ".wdata(wdata[k*W +: W]), .fault_flip(k == 0 && fault_flip),"),
        ("node_lane.v", r"^    output wire \[W-1:0\]  wdata,( +)// (.*)\n",
         "    output wire [W-1:0]  wdata,\\1// \\2\n"
         "    input  wire          fault_flip, // planted fault: flip bit 0 of this write\n"),
        ("node_lane.v", r"^    assign wdata( +)= (.*);\n",
         "    assign wdata\\1= (\\2) ^ {{(W-1){1'b0}}, fault_flip};\n"),
    ],
    # FEC one cycle late
    "delay": [
        ("strand_core.v", r"^            assign dbg = \{wb_xyz, wb_idx_all, wb_valid_all, counter, nidx, uidx, fec, fv, phase\};\n",
         "            reg fec_late;  // planted fault\n"
         "            always @(posedge clk) fec_late <= reset ? 1'b0 : fec;\n"
         "            assign dbg = {wb_xyz, wb_idx_all, wb_valid_all, counter, nidx, uidx, fec_late, fv, phase};\n"),
    ],
    # the pipelined pass (ARCH = 1): a sweep one cycle short, so the next colour reads before
    # the last write of the previous one has landed (shows first as the colour changing early)
    "boundary": [
        ("chain_stream.v", r"^    localparam integer SP     = NS \+ 1 > LT \+ 4 \? NS \+ 1 : LT \+ 4; .*\n",
         "    localparam integer SP     = (NS + 1 > LT + 4 ? NS + 1 : LT + 4) - 1;  // planted fault: a sweep one cycle short\n"),
    ],
    # the pipelined pass: a sweep's period from the pipe's latency alone (LT + 4), not its slots
    # (NS + 1): on a long unit (slot-bound) the next colour starts before the sweep has issued
    # its last slots
    "slots_cut": [
        ("chain_stream.v", r"^    localparam integer SP     = NS \+ 1 > LT \+ 4 \? NS \+ 1 : LT \+ 4; .*\n",
         "    localparam integer SP     = LT + 4;  // planted fault: the period ignores the slots\n"),
    ],
    # the pipelined pass: toward_pipe's output register bypassed (every result a cycle early)
    "bypass": [
        ("toward_pipe.v", r"^    output reg  \[DIM\*W-1:0\] out_t,", "    output wire [DIM*W-1:0] out_t,"),
        ("toward_pipe.v", r"^    output reg              out_ok, ", "    output wire             out_ok, "),
        ("toward_pipe.v", r"^    output reg  \[TAG_W-1:0\] out_tag,", "    output wire [TAG_W-1:0] out_tag,"),
        ("toward_pipe.v", r"^    assign out_valid = v_q\[LATENCY-1\];\n", ""),
        ("toward_pipe.v", r"^        out_t   <= t_sum;\n        out_ok  <= ok_f;\n        out_tag <= tag_f;\n", ""),
        ("toward_pipe.v", r"^            assign out_p = p_out;\n            assign out_c = c_out;\n",
         "            assign out_p = p_f;\n            assign out_c = c_f;\n            wire unused_fault = &{1'b0, p_out, c_out};\n"),
        ("toward_pipe.v", r"^endmodule",
         "    // planted fault: the output stage bypassed\n"
         "    assign out_valid = v_q[LATENCY-2];\n    assign out_t = t_sum;\n    assign out_ok = ok_f;\n    assign out_tag = tag_f;\n\n"
         "endmodule"),
    ],
}

FAULTS["hazard"] = [
    # the pipelined pass: a unit's colours taken from its local stream position, not the
    # global node, so across a unit border at an odd node (or in a unit that streams
    # downward from an odd one) two neighbours are in flight in the same sweep, each
    # reading the other's old position
    ("chain_stream.v", r"^            localparam \[0:0\] S_PAR = S_PAR_I\[0:0\];",
     "            localparam [0:0] S_PAR = 1'b0 & S_PAR_I[0];  // planted fault: local colours"),
]

# graph_stream (a graph's pipelined pass): the colour ends ignored (but the memory's last), so
# a colour's first edge reads its nodes while the previous colour's writes are in flight
FAULTS["graph_hazard"] = [
    ("graph_stream.v", r"^    wire          ent_last = \(entry_ok && entry\[2\*AW\+W\]\) \|\| j == E_LAST;\n",
     "    wire          ent_last = (1'b0 && entry_ok && entry[2*AW+W]) || j == E_LAST;  // planted fault: no drains\n"),
]
# graph_stream: the drain after a colour one cycle short, so the next colour's first read
# comes in the cycle of the previous colour's last write
FAULTS["graph_boundary"] = [
    ("graph_stream.v", r"DRAIN_I = LT \+ 2;", "DRAIN_I = LT + 1;  // planted fault: a drain one cycle short"),
]

# node_unit's stage R (ARCH = 1) bypassed in the lanes: stage A takes port A's words as they
# come, which one cycle after their arrival are the next node's, so the pass steps every node
# from its successor's position and velocity
FAULTS["stage_r"] = [
    ("node_lane.v", r"^                assign q_a  = q_r;\n                assign qp_a = qp_r;\n                assign qa_a = qa_r;\n",
     "                assign q_a  = q_in;   // planted fault: stage R bypassed\n                assign qp_a = qp_in;\n"
     "                assign qa_a = qa_in;\n                wire unused_fault = &{1'b0, q_r, qp_r, qa_r};\n"),
]

# node_unit with PAIR (a pipelined chain's Verlet pass, a row of two nodes a clock): the odd
# node of a row takes the even node's pinned flag, so node 1 of a chain pinned at node 0 stays
# where it is
FAULTS["odd_pin"] = [
    ("node_unit.v", r"^            assign v_pin  = \{q_pin1, q_pin\};\n",
     "            assign v_pin  = {q_pin, q_pin};  // planted fault: the odd node takes the even one's pin\n"
     "            wire unused_fault = &{1'b0, q_pin1};\n"),
    # FUSE: the fused sweep's step (the same row of two nodes, read by the sweep)
    ("node_unit.v", r"^            assign arr_pin    = fuse_q \? \{pair_pinned_o, pair_pinned_e\} : v_pin;\n",
     "            assign arr_pin    = fuse_q ? {pair_pinned_e, pair_pinned_e} : v_pin;  // planted fault\n"
     "            wire unused_fault_fuse = &{1'b0, pair_pinned_o};\n"),
]

# frame_ctrl: CMD beside a step wins (the priority before the step's was given first), so a
# frame's step with a CMD in its cycle lays the chain out again instead of starting the frame
FAULTS["step_priority"] = [
    ("frame_ctrl.v", r"^    wire         walk = cmd_init && !GRAPH && !step;\n",
     "    wire         walk = cmd_init && !GRAPH;  // planted fault: CMD wins over step\n"),
    ("frame_ctrl.v", r"^    assign frame_start  = phase == PH_IDLE && step;\n",
     "    assign frame_start  = phase == PH_IDLE && !walk && step;\n"),
]

# the normalised datapath (MANTISSA > 0): the normaliser's shift one bit too far for lane x, so
# |d| (and with it the ratio rest / |d|) comes out wrong wherever d.x is not small
FAULTS["norm_shift"] = [
    ("fx_along_pipe.v", r"\.a\(ext\[FW-1:1\]\), \.s\(l_2\), \.y\(kept\)\);",
     ".a(ext[FW-1:1]), .s(l_2 + {{(LB-1){1'b0}}, k == 0}), .y(kept));  // planted fault: lane x one bit further"),
]

# The scene order a fault's build needs (the pipelined faults live in ARCH = 1 builds).
ORDER = {"boundary": "redblack", "slots_cut": "redblack", "bypass": "redblack", "hazard": "redblack",
         "graph_hazard": "redblack", "graph_boundary": "redblack", "stage_r": "redblack", "odd_pin": "redblack",
         "norm_shift": "redblack"}
# The scene a fault runs on, where it is not the default chain (tb/scenes/chain_q10_8.scene).
SCENE = {"graph_hazard": "tb/scenes/graph3d_q12.scene", "graph_boundary": "tb/scenes/graph3d_q12.scene",
         "slots_cut": "tb/scenes/chain_slot_bound.scene", "norm_shift": "tb/scenes/mantissa/chain_pair_3d_mb8.scene"}


def plant(name, out):
    """Copy rtl/ to out with fault `name` planted; raises SystemExit if it does not apply."""
    if name not in FAULTS:
        raise SystemExit(f"faults.py: no fault '{name}' (faults: {', '.join(FAULTS)})")
    rtl = os.path.join(ROOT, "rtl")
    os.makedirs(out, exist_ok=True)
    for f in os.listdir(rtl):
        if os.path.isfile(os.path.join(rtl, f)):   # the core's files (rtl/boards/ is not part of it)
            shutil.copyfile(os.path.join(rtl, f), os.path.join(out, f))
    for fname, pattern, repl in FAULTS[name]:
        path = os.path.join(out, fname)
        with open(path) as fh:
            src = fh.read()
        n = len(re.findall(pattern, src, re.M))
        if n != 1:
            raise SystemExit(f"faults.py: fault '{name}' no longer applies: rtl/{fname} has {n} matches of {pattern!r}")
        with open(path, "w") as fh:
            fh.write(re.sub(pattern, repl, src, flags=re.M))


def main():
    if sys.argv[1:] == ["--list"]:
        print("\n".join(FAULTS))
        return 0
    if len(sys.argv) != 3:
        raise SystemExit("usage: faults.py NAME OUTDIR | --list")
    plant(sys.argv[1], sys.argv[2])
    return 0


if __name__ == "__main__":
    sys.exit(main())
