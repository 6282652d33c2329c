"""test_axil.py - strand_axil (strand_core behind AXI4-Lite) against the C model, with cocotb.

Run by tb/cocotb/run_axil.py, which exports a scene with `strand hwgen` (config.hex: the
setup writes; mouse.hex: the pointer per frame; expected.hex: every node at every frame
end from the fixed-point frame engine) and builds tb/axil_top.v for it under Icarus.
The bus master is cocotbext-axi's AxiLiteMaster. The register map is strand_axil.v's
header; the core's register addresses come from build/gen/strand_regs.h.

Tests:
  scene_through_the_bus     load the scene through the bus, run its frames (the mouse
                            through MOUSE_*, step through CTRL, the end through the
                            interrupt), read every node back, compare with the model
                            bit for bit; the setup and the reads are issued back to back
  interleaved_transactions  reads and writes in flight at once on both channels
  wrong_addresses           SLVERR for reads of write-only or missing registers, writes
                            to read-only ones, nodes that do not exist, partial strobes
  writes_while_running      during a frame: a constant written again (OKAY, the frame
                            still ends where the model says), CTRL step, CMD, NODE and
                            EDGE refused with SLVERR and without effect
  back_to_back_writes       a start followed in the next cycle by a second start and a
                            CMD, and a CMD followed in the next cycle by a start: the
                            later ones are refused although the core is not busy yet
                            (the write stage holds the first); one frame runs
"""
import os
import re

import cocotb
from cocotb.clock import Clock
from cocotb.triggers import ClockCycles, Combine, RisingEdge, Timer
from cocotbext.axi import AxiLiteBus, AxiLiteMaster
from cocotbext.axi.constants import AxiResp

DIR = os.environ["STRAND_AXIL_DIR"]            # the hwgen export of the scene
GEN = os.environ["STRAND_GEN"]                 # build/gen
FRAMES = int(os.environ.get("STRAND_AXIL_FRAMES", "3"))

CTRL, STATUS, FRAMES_REG, INFO, NODES = 0x100, 0x104, 0x108, 0x10C, 0x110
MOUSE = [0x114, 0x118, 0x11C]
MOUSE_DOWN = 0x120


def defines(path, prefix):
    out = {}
    for line in open(path):
        m = re.match(rf"\s*(?:#define|`define)\s+{prefix}(\w+)\s+(\S+)", line)
        if m:
            v = m.group(2)
            out[m.group(1)] = int(v.split("'b")[-1], 2) if "'b" in v else int(v, 0)
    return out


REG = defines(os.path.join(GEN, "strand_regs.h"), "STRAND_REG_")
BUILD = defines(os.path.join(DIR, "params.vh"), "STRAND_")
W, M, K, DIM = BUILD["W"], BUILD["M"], BUILD["K"], BUILD["DIM"]
IW = max(1, (K - 1).bit_length())
AW = max(1, (M - 1).bit_length()) + IW
NODE_BASE = 1 << max(12, AW + 4)
MASK = (1 << W) - 1


def words(path):
    return [line.split() for line in open(path) if line.strip()]


CONFIG = [(int(w[0][:2], 16), int(w[0][2:], 16)) for w in words(os.path.join(DIR, "config.hex"))]
MOUSE_SCRIPT = [[int(x, 16) for x in w] for w in words(os.path.join(DIR, "mouse.hex"))]
EXPECTED = [[int(x, 16) for x in w] for w in words(os.path.join(DIR, "expected.hex"))]


def node_addr(i):
    return (i // K) << IW | (i % K)


def signed32(v):
    return v - (1 << 32) if v & (1 << 31) else v


def sext(v):
    v &= MASK
    return v - (1 << W) if v >> (W - 1) else v


async def start(dut):
    cocotb.start_soon(Clock(dut.clk, 10, units="ns").start())
    dut.reset.value = 1
    bus = AxiLiteMaster(AxiLiteBus.from_prefix(dut, "s_axil"), dut.clk, dut.reset, reset_active_level=True)
    await ClockCycles(dut.clk, 4)
    dut.reset.value = 0
    await ClockCycles(dut.clk, 2)
    return bus


async def write(bus, addr, value, resp=AxiResp.OKAY):
    r = await bus.write(addr, (value & 0xFFFFFFFF).to_bytes(4, "little"))
    assert r.resp == resp, f"write 0x{addr:x} = 0x{value:x}: {r.resp!r}, expected {resp!r}"


async def read(bus, addr, resp=AxiResp.OKAY):
    r = await bus.read(addr, 4)
    assert r.resp == resp, f"read 0x{addr:x}: {r.resp!r}, expected {resp!r}"
    return int.from_bytes(r.data, "little")


async def wait_idle(dut, bus, limit=200000):
    for _ in range(limit):
        if not await read(bus, STATUS) & 1:
            return
    raise AssertionError("the core stayed busy")


async def setup(dut, bus):
    """The setup writes, issued back to back (all in flight at once), then the init walk."""
    await Combine(*[cocotb.start_soon(write(bus, 4 * a, d)) for a, d in CONFIG])
    await wait_idle(dut, bus)


async def read_nodes(bus):
    """Every node, every axis, issued back to back."""
    jobs = [cocotb.start_soon(read(bus, NODE_BASE + 16 * node_addr(i) + 4 * k)) for i in range(M * K) for k in range(DIM)]
    await Combine(*jobs)
    return [[j.result() for j in jobs[i * DIM:(i + 1) * DIM]] for i in range(M * K)]


def check_frame(frame, got):
    for i, pos in enumerate(got):
        want = EXPECTED[frame * M * K + i][:DIM]
        for k in range(DIM):
            assert signed32(pos[k]) == sext(want[k]), \
                f"frame {frame + 1} node {i} axis {'xyz'[k]}: bus {signed32(pos[k])}, model {sext(want[k])}"


async def run_frame(dut, bus, frame):
    down, mx, my, mz = MOUSE_SCRIPT[frame]
    for k, v in enumerate([mx, my, mz][:DIM]):
        await write(bus, MOUSE[k], sext(v))
    await write(bus, MOUSE_DOWN, down)
    await write(bus, CTRL, 0b11)              # step, interrupt enabled
    await RisingEdge(dut.irq)
    assert await read(bus, STATUS) == 0b110, "after the frame: idle, done, interrupt enabled"
    await write(bus, STATUS, 0b10)            # clear the frame-done flag
    await ClockCycles(dut.clk, 2)
    assert dut.irq.value == 0, "irq stays high after the clear"


@cocotb.test()
async def scene_through_the_bus(dut):
    bus = await start(dut)
    assert await read(bus, INFO) == (DIM << 24 | BUILD["F"] << 16 | W << 8)
    assert await read(bus, NODES) == (M << 16 | K)
    await setup(dut, bus)
    for frame in range(FRAMES):
        await run_frame(dut, bus, frame)
        check_frame(frame, await read_nodes(bus))
    assert await read(bus, FRAMES_REG) == FRAMES
    dut._log.info(f"{FRAMES} frames x {M * K} nodes through the bus, bit-exact with the model")


@cocotb.test()
async def interleaved_transactions(dut):
    bus = await start(dut)
    await setup(dut, bus)
    # writes and reads in flight at once: the mouse registers written and read back while
    # nodes are read; every answer is the right one
    values = [0x1234, -0x777, 0x55]
    jobs = []
    for k in range(DIM):
        jobs.append(cocotb.start_soon(write(bus, MOUSE[k], values[k])))
        jobs.append(cocotb.start_soon(read(bus, NODE_BASE + 16 * node_addr(M * K - 1) + 4 * k)))
        jobs.append(cocotb.start_soon(read(bus, STATUS)))
    await Combine(*jobs)
    for k in range(DIM):
        assert signed32(await read(bus, MOUSE[k])) == sext(values[k])
    # no frame ran: two reads of a node back to back give the same answer, and a frame
    # started now still ends where the model says
    twice = [cocotb.start_soon(read(bus, NODE_BASE + 4)) for _ in range(2)]
    await Combine(*twice)
    assert twice[0].result() == twice[1].result()
    await run_frame(dut, bus, 0)
    check_frame(0, await read_nodes(bus))


@cocotb.test()
async def wrong_addresses(dut):
    bus = await start(dut)
    await read(bus, 4 * REG["GDT2_X"], AxiResp.SLVERR)         # a core register: write only
    await read(bus, 4 * 63, AxiResp.SLVERR)                    # no such register
    await write(bus, 4 * 63, 1, AxiResp.SLVERR)
    await write(bus, 4 * REG["COUNT"], 1, AxiResp.SLVERR)      # the first address past the map
    await write(bus, FRAMES_REG, 1, AxiResp.SLVERR)            # read only
    await write(bus, INFO, 1, AxiResp.SLVERR)
    await read(bus, 0x124, AxiResp.SLVERR)                     # past the shell's registers
    await read(bus, 0x102, AxiResp.SLVERR)                     # not word aligned
    await read(bus, NODE_BASE + 12, AxiResp.SLVERR)            # axis 3
    if DIM == 2:
        await read(bus, NODE_BASE + 8, AxiResp.SLVERR)         # z in 2D
        await read(bus, MOUSE[2], AxiResp.SLVERR)
    if K & (K - 1):                                            # a node index past K in a unit
        await read(bus, NODE_BASE + 16 * K, AxiResp.SLVERR)
    if M & (M - 1):                                            # a unit past M
        await read(bus, NODE_BASE + 16 * (M << IW), AxiResp.SLVERR)
    r = await bus.write(MOUSE[0], b"\x01\x02")                 # two byte strobes only
    assert r.resp == AxiResp.SLVERR
    assert await read(bus, MOUSE[0]) == 0, "a refused write must not act"
    await read(bus, NODE_BASE + 16 * node_addr(M * K - 1))     # the last node is there
    await read(bus, STATUS)


@cocotb.test()
async def writes_while_running(dut):
    bus = await start(dut)
    await setup(dut, bus)
    for frame in range(min(FRAMES, 2)):
        down, mx, my, mz = MOUSE_SCRIPT[frame]
        for k, v in enumerate([mx, my, mz][:DIM]):
            await write(bus, MOUSE[k], sext(v))
        await write(bus, MOUSE_DOWN, down)
        await write(bus, CTRL, 0b01)
        await ClockCycles(dut.clk, 20)
        assert await read(bus, STATUS) & 1, "the frame is under way"
        # a run-time constant written again with its value: accepted, nothing changes
        gdt2 = [d for a, d in CONFIG if a == REG["GDT2_Y"]]
        await write(bus, 4 * REG["GDT2_Y"], sext(gdt2[-1]))
        # what loads the body or starts a frame is refused while busy, and does nothing
        await write(bus, CTRL, 0b01, AxiResp.SLVERR)
        await write(bus, 4 * REG["CMD"], 1, AxiResp.SLVERR)
        await write(bus, 4 * REG["NODE"], 0, AxiResp.SLVERR)
        await write(bus, 4 * REG["EDGE"], 0, AxiResp.SLVERR)
        await wait_idle(dut, bus)
        assert dut.irq.value == 0, "the interrupt is disabled"
        check_frame(frame, await read_nodes(bus))
    assert await read(bus, FRAMES_REG) == min(FRAMES, 2), "a refused step started no frame"
    await Timer(1, "ns")


async def accept_cycles(dut, log):
    """The clock cycle of every write the shell accepts (awvalid and awready high)."""
    cycle = 0
    while True:
        await RisingEdge(dut.clk)
        cycle += 1
        if dut.s_axil_awvalid.value == 1 and dut.s_axil_awready.value == 1:
            log.append(cycle)


async def back_to_back(dut, bus, writes):
    """Issue writes at once; check each response and that the shell took them in
    consecutive cycles, so each one met the one before it in the write stage."""
    log = []
    monitor = cocotb.start_soon(accept_cycles(dut, log))
    await Combine(*[cocotb.start_soon(write(bus, a, v, r)) for a, v, r in writes])
    monitor.kill()
    assert len(log) == len(writes) and log == list(range(log[0], log[0] + len(writes))), \
        f"the writes were accepted in cycles {log}, not back to back"


@cocotb.test()
async def back_to_back_writes(dut):
    bus = await start(dut)
    await setup(dut, bus)
    # a CMD that does nothing (bit 0 clear) still holds off a start in the next cycle
    await back_to_back(dut, bus, [(4 * REG["CMD"], 0, AxiResp.OKAY), (CTRL, 0b01, AxiResp.SLVERR)])
    await ClockCycles(dut.clk, 4)
    assert await read(bus, STATUS) & 1 == 0, "a refused start started a frame"
    down, mx, my, mz = MOUSE_SCRIPT[0]
    for k, v in enumerate([mx, my, mz][:DIM]):
        await write(bus, MOUSE[k], sext(v))
    await write(bus, MOUSE_DOWN, down)
    # a start, then a second start and a CMD while the first is still in the write stage
    await back_to_back(dut, bus, [(CTRL, 0b01, AxiResp.OKAY), (CTRL, 0b01, AxiResp.SLVERR),
                                  (4 * REG["CMD"], 1, AxiResp.SLVERR), (CTRL, 0b01, AxiResp.SLVERR)])
    await wait_idle(dut, bus)
    check_frame(0, await read_nodes(bus))
    assert await read(bus, FRAMES_REG) == 1, "one frame ran"
