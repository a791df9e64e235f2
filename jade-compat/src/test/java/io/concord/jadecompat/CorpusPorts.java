package io.concord.jadecompat;

import java.io.IOException;
import java.net.DatagramSocket;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.util.concurrent.ThreadLocalRandom;

/** A free base port on loopback with room for a platform's range (JADE takes the base, Concord 200 ports from it). */
final class CorpusPorts {
    private CorpusPorts() {
    }

    static int freeBase() {
        for (int attempt = 0; attempt < 50; attempt++) {
            int base = 30_000 + 200 * ThreadLocalRandom.current().nextInt(150);
            if (free(base) && free(base + 1) && free(base + 2)) {
                return base;
            }
        }
        throw new IllegalStateException("no free port range found on loopback");
    }

    private static boolean free(int port) {
        InetAddress lo = InetAddress.getLoopbackAddress();
        try (ServerSocket s = new ServerSocket(port, 1, lo); DatagramSocket d = new DatagramSocket(port, lo)) {
            return s.getLocalPort() == port && d.getLocalPort() == port;
        } catch (IOException e) {
            return false;
        }
    }
}
