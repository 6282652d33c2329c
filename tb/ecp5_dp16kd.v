`default_nettype none
`timescale 1ns / 1ps

/*
 * ecp5_dp16kd - a behavioural model of the ECP5 DP16KD (an 18 Kbit sysMEM block RAM) for
 * simulating Yosys's ECP5 netlists, as far as Yosys's block-RAM mapping uses it
 * (share/ecp5/brams_map.v: true dual port with widths 1, 2, 4, 9 and 18 per port, and the
 * pseudo dual port whose 36-bit write port A uses DIA and DIB and whose 36-bit read port B
 * gives DOA and DOB). Yosys ships the block as a black box only (cells_sim.v declares its
 * pins and parameters, with no behaviour); simulated that way its outputs are constant and
 * every read of a netlist's block RAM is wrong.
 *
 * Behaviour, from Lattice's description of the sysMEM block (ECP5 memory usage guide):
 *   - the 18,432 bits hold 2,048 9-bit bytes for the widths 9, 18 and 36 and 4,096 4-bit
 *     nibbles (16,384 bits) for 1, 2 and 4; a word of width w sits at address AD[13:k] with
 *     2^k = w rounded down to a power of two (AD[13:5] at 36, AD[13:4] at 18, AD[13:3] at 9);
 *     at 18 the low address pins AD[1:0] are the byte write enables of bits [8:0] and
 *     [17:9], at 36 AD[3:0] those of its four 9-bit bytes;
 *   - at a rising clock edge with CE high (and the chip select matching CSDECODE) a port
 *     with WE high writes, and its data output follows WRITEMODE: NORMAL holds it,
 *     WRITETHROUGH shows the word as written, READBEFOREWRITE the word before the write;
 *     a port with WE low reads the word into its output latch;
 *   - REGMODE OUTREG adds an output register (loaded from the latch when OCE is high) and so
 *     one cycle of latency; NOREG gives the latch;
 *   - both ports run on one clock: the edges of CLKA | CLKB, the two pins being one net or
 *     an unused port's pin tied low (a read-only block, as a ROM, may use port B alone); a
 *     port in use whose clock does not rise at such an edge stops the simulation;
 *   - a port reading bits that the other port writes at the same edge (its enabled bytes)
 *     reads undefined values (Lattice guarantees nothing across ports, and Yosys's mapping
 *     assumes nothing): here those bits of the old word inverted, so that a comparison with
 *     the RTL fails if a netlist ever uses them. Both ports writing one byte at one edge
 *     stores an undefined word: here the inverted port A data.
 * INITVAL_00..3F give the initial contents of the 9/18/36 family as Yosys writes them:
 * sixteen 18-bit words per 320-bit value, each in a 20-bit slot. Anything else (a reset
 * pulse, a clock inverted, the two ports on different clocks, a chip select other than
 * "0b000", an initial value in the 1/2/4 family, a width not in the list, a 36-bit port
 * used the other way) stops the simulation with an error, so the model is never used
 * beyond what it covers. The timing of the real block (its clock-to-output) is not modelled.
 */
/* verilator lint_off DECLFILENAME */  // the module carries the vendor primitive's name
module DP16KD #(
/* verilator lint_on DECLFILENAME */
    parameter integer DATA_WIDTH_A = 18,
    parameter integer DATA_WIDTH_B = 18,
    parameter REGMODE_A = "NOREG",
    parameter REGMODE_B = "NOREG",
    parameter RESETMODE = "SYNC",
    parameter ASYNC_RESET_RELEASE = "SYNC",
    parameter CSDECODE_A = "0b000",
    parameter CSDECODE_B = "0b000",
    parameter WRITEMODE_A = "NORMAL",
    parameter WRITEMODE_B = "NORMAL",
    parameter CLKAMUX = "CLKA",
    parameter CLKBMUX = "CLKB",
    parameter GSR = "ENABLED",
    parameter INIT_DATA = "STATIC",
    parameter [319:0] INITVAL_00 = 320'h0,
    parameter [319:0] INITVAL_01 = 320'h0,
    parameter [319:0] INITVAL_02 = 320'h0,
    parameter [319:0] INITVAL_03 = 320'h0,
    parameter [319:0] INITVAL_04 = 320'h0,
    parameter [319:0] INITVAL_05 = 320'h0,
    parameter [319:0] INITVAL_06 = 320'h0,
    parameter [319:0] INITVAL_07 = 320'h0,
    parameter [319:0] INITVAL_08 = 320'h0,
    parameter [319:0] INITVAL_09 = 320'h0,
    parameter [319:0] INITVAL_0A = 320'h0,
    parameter [319:0] INITVAL_0B = 320'h0,
    parameter [319:0] INITVAL_0C = 320'h0,
    parameter [319:0] INITVAL_0D = 320'h0,
    parameter [319:0] INITVAL_0E = 320'h0,
    parameter [319:0] INITVAL_0F = 320'h0,
    parameter [319:0] INITVAL_10 = 320'h0,
    parameter [319:0] INITVAL_11 = 320'h0,
    parameter [319:0] INITVAL_12 = 320'h0,
    parameter [319:0] INITVAL_13 = 320'h0,
    parameter [319:0] INITVAL_14 = 320'h0,
    parameter [319:0] INITVAL_15 = 320'h0,
    parameter [319:0] INITVAL_16 = 320'h0,
    parameter [319:0] INITVAL_17 = 320'h0,
    parameter [319:0] INITVAL_18 = 320'h0,
    parameter [319:0] INITVAL_19 = 320'h0,
    parameter [319:0] INITVAL_1A = 320'h0,
    parameter [319:0] INITVAL_1B = 320'h0,
    parameter [319:0] INITVAL_1C = 320'h0,
    parameter [319:0] INITVAL_1D = 320'h0,
    parameter [319:0] INITVAL_1E = 320'h0,
    parameter [319:0] INITVAL_1F = 320'h0,
    parameter [319:0] INITVAL_20 = 320'h0,
    parameter [319:0] INITVAL_21 = 320'h0,
    parameter [319:0] INITVAL_22 = 320'h0,
    parameter [319:0] INITVAL_23 = 320'h0,
    parameter [319:0] INITVAL_24 = 320'h0,
    parameter [319:0] INITVAL_25 = 320'h0,
    parameter [319:0] INITVAL_26 = 320'h0,
    parameter [319:0] INITVAL_27 = 320'h0,
    parameter [319:0] INITVAL_28 = 320'h0,
    parameter [319:0] INITVAL_29 = 320'h0,
    parameter [319:0] INITVAL_2A = 320'h0,
    parameter [319:0] INITVAL_2B = 320'h0,
    parameter [319:0] INITVAL_2C = 320'h0,
    parameter [319:0] INITVAL_2D = 320'h0,
    parameter [319:0] INITVAL_2E = 320'h0,
    parameter [319:0] INITVAL_2F = 320'h0,
    parameter [319:0] INITVAL_30 = 320'h0,
    parameter [319:0] INITVAL_31 = 320'h0,
    parameter [319:0] INITVAL_32 = 320'h0,
    parameter [319:0] INITVAL_33 = 320'h0,
    parameter [319:0] INITVAL_34 = 320'h0,
    parameter [319:0] INITVAL_35 = 320'h0,
    parameter [319:0] INITVAL_36 = 320'h0,
    parameter [319:0] INITVAL_37 = 320'h0,
    parameter [319:0] INITVAL_38 = 320'h0,
    parameter [319:0] INITVAL_39 = 320'h0,
    parameter [319:0] INITVAL_3A = 320'h0,
    parameter [319:0] INITVAL_3B = 320'h0,
    parameter [319:0] INITVAL_3C = 320'h0,
    parameter [319:0] INITVAL_3D = 320'h0,
    parameter [319:0] INITVAL_3E = 320'h0,
    parameter [319:0] INITVAL_3F = 320'h0
) (
    input  wire DIA17, DIA16, DIA15, DIA14, DIA13, DIA12, DIA11, DIA10, DIA9, DIA8, DIA7, DIA6, DIA5, DIA4,
    input  wire DIA3, DIA2, DIA1, DIA0,
    input  wire ADA13, ADA12, ADA11, ADA10, ADA9, ADA8, ADA7, ADA6, ADA5, ADA4, ADA3, ADA2, ADA1, ADA0,
    input  wire CEA, OCEA, CLKA, WEA, RSTA,
    input  wire CSA2, CSA1, CSA0,
    output wire DOA17, DOA16, DOA15, DOA14, DOA13, DOA12, DOA11, DOA10, DOA9, DOA8, DOA7, DOA6, DOA5, DOA4,
    output wire DOA3, DOA2, DOA1, DOA0,
    input  wire DIB17, DIB16, DIB15, DIB14, DIB13, DIB12, DIB11, DIB10, DIB9, DIB8, DIB7, DIB6, DIB5, DIB4,
    input  wire DIB3, DIB2, DIB1, DIB0,
    input  wire ADB13, ADB12, ADB11, ADB10, ADB9, ADB8, ADB7, ADB6, ADB5, ADB4, ADB3, ADB2, ADB1, ADB0,
    input  wire CEB, OCEB, CLKB, WEB, RSTB,
    input  wire CSB2, CSB1, CSB0,
    output wire DOB17, DOB16, DOB15, DOB14, DOB13, DOB12, DOB11, DOB10, DOB9, DOB8, DOB7, DOB6, DOB5, DOB4,
    output wire DOB3, DOB2, DOB1, DOB0
);
    wire [17:0] dia = {DIA17, DIA16, DIA15, DIA14, DIA13, DIA12, DIA11, DIA10, DIA9, DIA8, DIA7, DIA6, DIA5,
                       DIA4, DIA3, DIA2, DIA1, DIA0};
    wire [17:0] dib = {DIB17, DIB16, DIB15, DIB14, DIB13, DIB12, DIB11, DIB10, DIB9, DIB8, DIB7, DIB6, DIB5,
                       DIB4, DIB3, DIB2, DIB1, DIB0};
    wire [13:0] ada = {ADA13, ADA12, ADA11, ADA10, ADA9, ADA8, ADA7, ADA6, ADA5, ADA4, ADA3, ADA2, ADA1, ADA0};
    wire [13:0] adb = {ADB13, ADB12, ADB11, ADB10, ADB9, ADB8, ADB7, ADB6, ADB5, ADB4, ADB3, ADB2, ADB1, ADB0};

    // the address bits below a word's address (log2 of the width rounded down to a power of two)
    function integer low_bits(input integer width);
        case (width)
            1: low_bits = 0;
            2: low_bits = 1;
            4: low_bits = 2;
            9: low_bits = 3;
            18: low_bits = 4;
            default: low_bits = 5;  // 36
        endcase
    endfunction
    // string parameters against literals of other lengths: Verilog pads the shorter with zeros
    /* verilator lint_off WIDTH */
    localparam THROUGH_A = WRITEMODE_A == "WRITETHROUGH", BEFORE_A = WRITEMODE_A == "READBEFOREWRITE";
    localparam THROUGH_B = WRITEMODE_B == "WRITETHROUGH", BEFORE_B = WRITEMODE_B == "READBEFOREWRITE";
    localparam OUTREG_A = REGMODE_A == "OUTREG", OUTREG_B = REGMODE_B == "OUTREG";
    /* verilator lint_on WIDTH */
    localparam BYTES = DATA_WIDTH_A >= 9;   // the 9/18/36 family (else 1/2/4: nibbles)

    function [319:0] initval(input [5:0] idx);
        case (idx)
            6'h00: initval = INITVAL_00;
            6'h01: initval = INITVAL_01;
            6'h02: initval = INITVAL_02;
            6'h03: initval = INITVAL_03;
            6'h04: initval = INITVAL_04;
            6'h05: initval = INITVAL_05;
            6'h06: initval = INITVAL_06;
            6'h07: initval = INITVAL_07;
            6'h08: initval = INITVAL_08;
            6'h09: initval = INITVAL_09;
            6'h0A: initval = INITVAL_0A;
            6'h0B: initval = INITVAL_0B;
            6'h0C: initval = INITVAL_0C;
            6'h0D: initval = INITVAL_0D;
            6'h0E: initval = INITVAL_0E;
            6'h0F: initval = INITVAL_0F;
            6'h10: initval = INITVAL_10;
            6'h11: initval = INITVAL_11;
            6'h12: initval = INITVAL_12;
            6'h13: initval = INITVAL_13;
            6'h14: initval = INITVAL_14;
            6'h15: initval = INITVAL_15;
            6'h16: initval = INITVAL_16;
            6'h17: initval = INITVAL_17;
            6'h18: initval = INITVAL_18;
            6'h19: initval = INITVAL_19;
            6'h1A: initval = INITVAL_1A;
            6'h1B: initval = INITVAL_1B;
            6'h1C: initval = INITVAL_1C;
            6'h1D: initval = INITVAL_1D;
            6'h1E: initval = INITVAL_1E;
            6'h1F: initval = INITVAL_1F;
            6'h20: initval = INITVAL_20;
            6'h21: initval = INITVAL_21;
            6'h22: initval = INITVAL_22;
            6'h23: initval = INITVAL_23;
            6'h24: initval = INITVAL_24;
            6'h25: initval = INITVAL_25;
            6'h26: initval = INITVAL_26;
            6'h27: initval = INITVAL_27;
            6'h28: initval = INITVAL_28;
            6'h29: initval = INITVAL_29;
            6'h2A: initval = INITVAL_2A;
            6'h2B: initval = INITVAL_2B;
            6'h2C: initval = INITVAL_2C;
            6'h2D: initval = INITVAL_2D;
            6'h2E: initval = INITVAL_2E;
            6'h2F: initval = INITVAL_2F;
            6'h30: initval = INITVAL_30;
            6'h31: initval = INITVAL_31;
            6'h32: initval = INITVAL_32;
            6'h33: initval = INITVAL_33;
            6'h34: initval = INITVAL_34;
            6'h35: initval = INITVAL_35;
            6'h36: initval = INITVAL_36;
            6'h37: initval = INITVAL_37;
            6'h38: initval = INITVAL_38;
            6'h39: initval = INITVAL_39;
            6'h3A: initval = INITVAL_3A;
            6'h3B: initval = INITVAL_3B;
            6'h3C: initval = INITVAL_3C;
            6'h3D: initval = INITVAL_3D;
            6'h3E: initval = INITVAL_3E;
            6'h3F: initval = INITVAL_3F;
            default: initval = 320'h0;
        endcase
    endfunction

    // the array: 9-bit bytes for the 9/18/36 family, 4-bit nibbles for 1/2/4
    reg [8:0] bytes [0:2047];
    reg [3:0] nibbles [0:4095];
    integer i;
    reg [319:0] slots;
    reg [17:0] w18;
    initial begin
        /* verilator lint_off WIDTH */  // as above
        if (!((DATA_WIDTH_A == 1 || DATA_WIDTH_A == 2 || DATA_WIDTH_A == 4 || DATA_WIDTH_A == 9 ||
               DATA_WIDTH_A == 18 || DATA_WIDTH_A == 36) &&
              (DATA_WIDTH_B == 1 || DATA_WIDTH_B == 2 || DATA_WIDTH_B == 4 || DATA_WIDTH_B == 9 ||
               DATA_WIDTH_B == 18 || DATA_WIDTH_B == 36) &&
              ((DATA_WIDTH_A >= 9) == (DATA_WIDTH_B >= 9)) &&
              (REGMODE_A == "NOREG" || REGMODE_A == "OUTREG") &&
              (REGMODE_B == "NOREG" || REGMODE_B == "OUTREG") &&
              (WRITEMODE_A == "NORMAL" || WRITEMODE_A == "WRITETHROUGH" || WRITEMODE_A == "READBEFOREWRITE") &&
              (WRITEMODE_B == "NORMAL" || WRITEMODE_B == "WRITETHROUGH" || WRITEMODE_B == "READBEFOREWRITE") &&
              CSDECODE_A == "0b000" && CSDECODE_B == "0b000" && CLKAMUX == "CLKA" && CLKBMUX == "CLKB")) begin
            $display("FAIL DP16KD model: configuration not modelled in %m (widths %0d/%0d)", DATA_WIDTH_A,
                     DATA_WIDTH_B);
            $fatal(1);
        end
        /* verilator lint_on WIDTH */
        for (i = 0; i < 4096; i = i + 1) nibbles[i] = 4'd0;
        for (i = 0; i < 1024; i = i + 1) begin
            slots = initval(i[9:4]);
            w18 = slots[20 * (i % 16) +: 18];
            bytes[2 * i] = w18[8:0];
            bytes[2 * i + 1] = w18[17:9];
            if (!BYTES && w18 != 18'd0) begin
                $display("FAIL DP16KD model: initial contents of the 1/2/4 widths not modelled in %m");
                $fatal(1);
            end
        end
    end

    // the word of a width at an address (zero-extended to 36 bits), before this edge's writes
    function [35:0] word_at(input integer width, input [13:0] ad);
        integer idx;
        begin
            idx = {18'd0, ad} >> low_bits(width);
            word_at = 36'd0;
            case (width)
                1: word_at[0] = nibbles[idx >> 2][idx % 4];
                2: word_at[1:0] = nibbles[idx >> 1][2 * (idx % 2) +: 2];
                4: word_at[3:0] = nibbles[idx];
                9: word_at[8:0] = bytes[idx];
                18: word_at[17:0] = {bytes[2 * idx + 1], bytes[2 * idx]};
                default: word_at = {bytes[4 * idx + 3], bytes[4 * idx + 2], bytes[4 * idx + 1], bytes[4 * idx]};
            endcase
        end
    endfunction

    // the bits of the array a word covers: [first, first + width) in the family's bit order
    function integer first_bit(input integer width, input [13:0] ad);
        first_bit = ({18'd0, ad} >> low_bits(width)) * width;
    endfunction

    // the bits of a word read (width wr at address ar) that a write (width ww at aw, byte
    // enables be) stores at the same edge: those a read cannot rely on
    function [35:0] written_bits(input integer wr, input [13:0] ar, input integer ww, input [13:0] aw,
                                 input [3:0] be);
        integer k, p;
        begin
            written_bits = 36'd0;
            // (the words apart, the common case, the loop finds nothing)
            if (first_bit(wr, ar) < first_bit(ww, aw) + ww && first_bit(ww, aw) < first_bit(wr, ar) + wr)
            for (k = 0; k < wr; k = k + 1) begin
                p = first_bit(wr, ar) + k - first_bit(ww, aw);
                if (p >= 0 && p < ww && (ww < 18 || be[p / 9])) written_bits[k] = 1'b1;
            end
        end
    endfunction

    // the byte enables of a write (all ones below 18 bits)
    function [3:0] byte_enables(input integer width, input [3:0] ad);
        byte_enables = width == 36 ? ad[3:0] : width == 18 ? {2'b00, ad[1:0]} : 4'b1111;
    endfunction

    // one edge updates the array in order (old words read, writes, words as written read):
    // blocking assignments to the array and its temporaries, the outputs non-blocking
    /* verilator lint_off BLKSEQ */
    task write_word(input integer width, input [13:0] ad, input [35:0] data, input [3:0] be);
        integer idx, j;
        reg [3:0] nib;
        begin
            idx = {18'd0, ad} >> low_bits(width);
            case (width)
                1: begin nib = nibbles[idx >> 2]; nib[idx % 4] = data[0]; nibbles[idx >> 2] = nib; end
                2: begin nib = nibbles[idx >> 1]; nib[2 * (idx % 2) +: 2] = data[1:0]; nibbles[idx >> 1] = nib; end
                4: nibbles[idx] = data[3:0];
                9: bytes[idx] = data[8:0];
                default:
                    for (j = 0; j < width / 9; j = j + 1)
                        if (be[j]) bytes[(width / 9) * idx + j] = data[9 * j +: 9];
            endcase
        end
    endtask

    // a port's output latch after an edge: held when the port is idle; a read gives the old word
    // (the bits the other port writes inverted); a write gives what WRITEMODE says (new: the
    // word as written, after this edge's writes)
    function [35:0] port_output(input [35:0] held, input reads, input writes, input shows_new, input shows_old,
                                input [35:0] old, input [35:0] clash, input [35:0] new_word);
        port_output = !reads ? held : !writes ? old ^ clash : shows_new ? new_word : shows_old ? old : held;
    endfunction

    // the ports: a 36-bit port A only writes (DIB carries its high half), a 36-bit port B only
    // reads (DOA carries its low half)
    wire en_a = CEA && {CSA2, CSA1, CSA0} == 3'b000;
    wire en_b = CEB && {CSB2, CSB1, CSB0} == 3'b000;
    wire [35:0] din_a = DATA_WIDTH_A == 36 ? {dib, dia} : {18'd0, dia};
    wire writes_a = en_a && WEA;
    wire writes_b = en_b && WEB;
    wire reads_a = en_a && DATA_WIDTH_A != 36;
    wire reads_b = en_b;

    reg [35:0] latch_a = 36'd0, latch_b = 36'd0, oreg_a = 36'd0, oreg_b = 36'd0;
    wire [3:0] be_a = byte_enables(DATA_WIDTH_A, ada[3:0]);
    wire [3:0] be_b = byte_enables(DATA_WIDTH_B, adb[3:0]);
    reg [35:0] old_a, old_b, clash_a, clash_b;
    // the one clock (see the header): a port's pin tied low when it is unused
    wire edge_clk = CLKA | CLKB;
    always @(posedge edge_clk) begin
        if (RSTA || RSTB || (DATA_WIDTH_B == 36 && WEB) || (DATA_WIDTH_A == 36 && DATA_WIDTH_B != 36 && WEB)) begin
            $display("FAIL DP16KD model: a reset, or a write on a read-only 36-bit port, not modelled in %m");
            $fatal(1);
        end
        // the output registers load the latches as they were before this edge
        if (OCEA) oreg_a <= latch_a;
        if (OCEB) oreg_b <= latch_b;
        old_a = word_at(DATA_WIDTH_A, ada);
        old_b = word_at(DATA_WIDTH_B, adb);
        // what each port's read cannot rely on: the bits the other port writes at this edge
        clash_a = writes_b ? written_bits(DATA_WIDTH_A, ada, DATA_WIDTH_B, adb, be_b) : 36'd0;
        clash_b = writes_a ? written_bits(DATA_WIDTH_B, adb, DATA_WIDTH_A, ada, be_a) : 36'd0;
        if (writes_a) write_word(DATA_WIDTH_A, ada, din_a, be_a);
        if (writes_b) write_word(DATA_WIDTH_B, adb, {18'd0, dib}, be_b);
        if (writes_a && writes_b && |(written_bits(DATA_WIDTH_A, ada, DATA_WIDTH_B, adb, be_b) &
                                      written_bits(DATA_WIDTH_A, ada, DATA_WIDTH_A, ada, be_a)))
            write_word(DATA_WIDTH_A, ada, ~din_a, be_a);  // both ports write a byte: undefined, poisoned
        latch_a <= port_output(latch_a, reads_a, writes_a, THROUGH_A, BEFORE_A, old_a, clash_a,
                               word_at(DATA_WIDTH_A, ada));
        latch_b <= port_output(latch_b, reads_b, writes_b, THROUGH_B, BEFORE_B, old_b, clash_b,
                               word_at(DATA_WIDTH_B, adb));
    end
    /* verilator lint_on BLKSEQ */
    // one clock for both ports (the collision rules above compare the two ports at one edge):
    // a port in use must see every edge
    always @(posedge edge_clk) if ((en_a && CLKA !== 1'b1) || (en_b && CLKB !== 1'b1)) begin
        $display("FAIL DP16KD model: a port in use is clocked off the block's one clock in %m (one common clock is modelled)");
        $fatal(1);
    end

    wire [35:0] out_a = OUTREG_A ? oreg_a : latch_a;
    wire [35:0] out_b = OUTREG_B ? oreg_b : latch_b;
    // a 36-bit read port B drives DOA with its low half and DOB with its high half
    wire [17:0] doa = DATA_WIDTH_B == 36 ? out_b[17:0] : out_a[17:0];
    wire [17:0] dob = DATA_WIDTH_B == 36 ? out_b[35:18] : out_b[17:0];
    assign {DOA17, DOA16, DOA15, DOA14, DOA13, DOA12, DOA11, DOA10, DOA9, DOA8, DOA7, DOA6, DOA5, DOA4, DOA3,
            DOA2, DOA1, DOA0} = doa;
    assign {DOB17, DOB16, DOB15, DOB14, DOB13, DOB12, DOB11, DOB10, DOB9, DOB8, DOB7, DOB6, DOB5, DOB4, DOB3,
            DOB2, DOB1, DOB0} = dob;

    wire unused = &{1'b0, RESETMODE, ASYNC_RESET_RELEASE, GSR, INIT_DATA, out_a[35:18]};
endmodule

`resetall
