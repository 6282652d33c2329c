// board_sim.cpp - a board top (rtl/boards/*_top.v) under Verilator, its UART pins wired
// to a pseudo-terminal, so that `strand board --port PTY SCENE` talks to the simulated
// board exactly as to a real one (tb/board_check.sh, make test).
//
// usage: board_sim --pty-file FILE [--clks-per-bit N] [--max-seconds S]
//
// The pseudo-terminal's name is written to FILE once it is ready. Bytes the host writes
// are driven onto the board's RX pin bit by bit (8N1, N clock cycles a bit: the top's
// CLKS_PER_BIT), and the board's TX pin is sampled in the middle of every bit and each
// byte written back to the host. The simulation runs until it is killed, or for at most
// --max-seconds of wall time (default 600).
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <deque>
#include <fcntl.h>
#include <memory>
#include <string>
#include <termios.h>
#include <unistd.h>

#include "Vboard.h"
#include "verilated.h"

int main(int argc, char **argv) {
    std::string pty_file;
    long cpb = 104;
    double max_seconds = 600;
    for (int i = 1; i < argc; i++) {
        std::string a = argv[i];
        if (a == "--pty-file" && i + 1 < argc) pty_file = argv[++i];
        else if (a == "--clks-per-bit" && i + 1 < argc) cpb = std::atol(argv[++i]);
        else if (a == "--max-seconds" && i + 1 < argc) max_seconds = std::atof(argv[++i]);
        else if (a[0] != '+') {
            std::fprintf(stderr, "usage: board_sim --pty-file FILE [--clks-per-bit N] [--max-seconds S]\n");
            return 2;
        }
    }
    if (pty_file.empty() || cpb < 4) {
        std::fprintf(stderr, "board_sim: --pty-file is needed, and --clks-per-bit must be at least 4\n");
        return 2;
    }
    int master = posix_openpt(O_RDWR | O_NOCTTY);
    if (master < 0 || grantpt(master) || unlockpt(master)) {
        std::fprintf(stderr, "board_sim: no pseudo-terminal: %s\n", std::strerror(errno));
        return 1;
    }
    const char *slave_name = ptsname(master);
    // keep the slave open here too (raw), so that the line stays raw and the master never
    // reads EIO between the host's open and close
    int slave = open(slave_name, O_RDWR | O_NOCTTY);
    struct termios t;
    if (slave < 0 || tcgetattr(slave, &t)) {
        std::fprintf(stderr, "board_sim: %s: %s\n", slave_name, std::strerror(errno));
        return 1;
    }
    cfmakeraw(&t);
    tcsetattr(slave, TCSANOW, &t);
    fcntl(master, F_SETFL, fcntl(master, F_GETFL) | O_NONBLOCK);
    {
        std::string tmp = pty_file + ".tmp";
        FILE *f = std::fopen(tmp.c_str(), "w");
        if (!f) {
            std::fprintf(stderr, "board_sim: cannot write %s\n", tmp.c_str());
            return 1;
        }
        std::fprintf(f, "%s\n", slave_name);
        std::fclose(f);
        std::rename(tmp.c_str(), pty_file.c_str());
    }

    auto ctx = std::make_unique<VerilatedContext>();
    ctx->commandArgs(argc, argv);
    auto top = std::make_unique<Vboard>(ctx.get());
    std::deque<uint8_t> to_board;
    // RX driver: the byte on the line and where in it we are
    long rx_count = 0;
    int rx_bit = -1;   // -1 idle, 0 start, 1..8 data, 9 stop
    uint8_t rx_byte = 0;
    // TX sampler
    long tx_count = 0;
    int tx_bit = -1;
    uint8_t tx_byte = 0;
    auto t0 = std::chrono::steady_clock::now();
    top->RX = 1;
    top->BTN_N = 1;
    for (uint64_t cyc = 0;; cyc++) {
        if ((cyc & 1023) == 0) {
            uint8_t buf[256];
            ssize_t n = read(master, buf, sizeof buf);
            for (ssize_t i = 0; i < n; i++) to_board.push_back(buf[i]);
            if ((cyc & 0xfffff) == 0 &&
                std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() > max_seconds)
                break;
        }
        // drive RX
        if (rx_bit < 0 && !to_board.empty()) {
            rx_byte = to_board.front();
            to_board.pop_front();
            rx_bit = 0;
            rx_count = cpb;
        }
        if (rx_bit >= 0) {
            top->RX = rx_bit == 0 ? 0 : rx_bit <= 8 ? (rx_byte >> (rx_bit - 1)) & 1 : 1;
            if (--rx_count == 0) {
                rx_count = cpb;
                if (++rx_bit > 9) rx_bit = -1;
            }
        } else
            top->RX = 1;
        top->CLK = 0;
        top->eval();
        top->CLK = 1;
        top->eval();
        // sample TX in the middle of each bit
        if (tx_bit < 0) {
            if (!top->TX) {
                tx_bit = 0;
                tx_count = cpb / 2;
            }
        } else if (--tx_count == 0) {
            tx_count = cpb;
            if (tx_bit >= 1 && tx_bit <= 8) tx_byte = (uint8_t)(tx_byte >> 1 | (top->TX ? 0x80 : 0));
            if (tx_bit == 9) {
                if (top->TX) { // a good stop bit
                    ssize_t w;
                    do w = write(master, &tx_byte, 1);
                    while (w < 0 && (errno == EINTR || errno == EAGAIN));
                }
                tx_bit = -1;
            } else
                tx_bit++;
        }
    }
    top->final();
    close(slave);
    close(master);
    return 0;
}
