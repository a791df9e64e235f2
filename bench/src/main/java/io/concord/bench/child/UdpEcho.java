package io.concord.bench.child;

import java.net.InetSocketAddress;
import java.net.SocketAddress;
import java.nio.ByteBuffer;
import java.nio.channels.DatagramChannel;

/** A UDP echo in its own process, for the two-process baseline: prints its port, echoes until stdin closes. */
public final class UdpEcho {
    private UdpEcho() {
    }

    public static void main(String[] args) throws Exception {
        DatagramChannel ch = DatagramChannel.open().bind(new InetSocketAddress("127.0.0.1", 0));
        System.out.println("PORT " + ((InetSocketAddress) ch.getLocalAddress()).getPort());
        System.out.flush();
        Thread echo = new Thread(() -> {
            ByteBuffer buf = ByteBuffer.allocateDirect(2048);
            try {
                while (true) {
                    buf.clear();
                    SocketAddress from = ch.receive(buf);
                    buf.flip();
                    ch.send(buf, from);
                }
            } catch (Exception e) {
                // closed
            }
        });
        echo.setDaemon(true);
        echo.start();
        while (System.in.read() >= 0) {
            // until the parent closes our input
        }
        ch.close();
    }
}
