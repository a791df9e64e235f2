package io.concord.layers;

import java.io.PrintStream;
import java.util.ServiceLoader;

/**
 * Starts the web console of a platform, found with {@link ServiceLoader}:
 * {@code concord-console} provides it, so that {@code Boot -console 7070} and
 * {@link Platform.Builder#console(String)} need nothing but that jar on the class path.
 */
public interface ConsoleProvider {

    /**
     * Starts a console for the platform on {@code [host:]port}; closed with the platform.
     *
     * @param out where to print its address (with the token, when one is needed)
     * @throws IllegalArgumentException saying what is wrong with the address
     */
    AutoCloseable start(Platform platform, String hostPort, PrintStream out);
}
