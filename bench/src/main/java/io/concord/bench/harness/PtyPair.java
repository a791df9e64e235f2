package io.concord.bench.harness;

import com.fazecast.jSerialComm.SerialPort;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;

/** A pty pair made by socat in a temporary directory, the host's end and the board's: a serial cable on one machine. */
final class PtyPair implements AutoCloseable {
    final Path host;
    final Path board;
    private final Process socat;

    PtyPair(String prefix) throws IOException, InterruptedException {
        Path dir = Files.createTempDirectory(prefix);
        host = dir.resolve("host");
        board = dir.resolve("board");
        socat = new ProcessBuilder("socat", "pty,raw,echo=0,link=" + host, "pty,raw,echo=0,link=" + board)
                .redirectErrorStream(true).redirectOutput(ProcessBuilder.Redirect.DISCARD).start();
        long end = System.nanoTime() + 10_000_000_000L;
        while (!(Files.exists(host) && Files.exists(board))) {
            if (System.nanoTime() > end) {
                socat.destroyForcibly();
                throw new IllegalStateException("socat made no pty pair (is socat installed?)");
            }
            Thread.sleep(10);
        }
    }

    /** The board's end, opened 115200 8N1 for reads that never block (a board's loop polls it). */
    SerialPort openBoard() {
        SerialPort p = SerialPort.getCommPort(board.toString());
        p.setComPortParameters(115_200, 8, SerialPort.ONE_STOP_BIT, SerialPort.NO_PARITY);
        p.setComPortTimeouts(SerialPort.TIMEOUT_NONBLOCKING, 0, 0);
        if (!p.openPort()) {
            throw new IllegalStateException("cannot open " + board);
        }
        return p;
    }

    @Override
    public void close() {
        socat.destroyForcibly();
    }
}
