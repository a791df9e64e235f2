package io.concord.sim.board;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.function.BooleanSupplier;

/** A pair of connected pseudo-terminals made by socat, reached by two paths; removed when socat ends. */
final class Pty implements AutoCloseable {
    final Path host;
    final Path board;
    private Process socat;

    Pty(Path dir) throws IOException {
        this.host = dir.resolve("chair-host");
        this.board = dir.resolve("chair-board");
        start();
    }

    /** Starts socat (again): both paths appear. */
    void start() throws IOException {
        socat = new ProcessBuilder("socat", "pty,raw,echo=0,link=" + host, "pty,raw,echo=0,link=" + board)
                .redirectErrorStream(true).redirectOutput(ProcessBuilder.Redirect.DISCARD).start();
        await(() -> Files.exists(host) && Files.exists(board), 10_000, "socat's pty pair " + host + ", " + board);
    }

    /** Ends socat: both ptys close and their paths go, as an unplugged adapter's device does. */
    void unplug() {
        socat.destroy();
        await(() -> !Files.exists(host) && !Files.exists(board), 10_000, "the pty paths to go");
    }

    @Override
    public void close() {
        socat.destroyForcibly();
    }

    /** Polls a condition every 10 ms until it holds; fails after the limit. */
    static void await(BooleanSupplier c, long limitMs, String what) {
        long end = System.nanoTime() + limitMs * 1_000_000;
        while (!c.getAsBoolean()) {
            if (System.nanoTime() > end) {
                throw new AssertionError("waited " + limitMs + " ms for " + what);
            }
            try {
                Thread.sleep(10);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                throw new AssertionError(e);
            }
        }
    }
}
