package io.concord.console;

import io.concord.layers.ConsoleProvider;
import io.concord.layers.Platform;

import java.io.PrintStream;
import java.io.UncheckedIOException;

/** How {@code Boot -console} and {@code Platform.builder().console(...)} find the console. */
public final class ConsoleStarter implements ConsoleProvider {

    @Override
    public AutoCloseable start(Platform platform, String hostPort, PrintStream out) {
        try {
            Console c = Console.start(platform, Console.Config.parse(hostPort));
            out.println("console: " + c.uri() + (c.token() != null ? "  (every request needs this token)" : ""));
            return c;
        } catch (UncheckedIOException e) {
            throw new IllegalStateException(e.getMessage(), e);
        }
    }
}
