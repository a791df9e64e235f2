package io.concord.bench.jmh;

import io.concord.bench.child.UdpEcho;

import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.Level;
import org.openjdk.jmh.annotations.OperationsPerInvocation;
import org.openjdk.jmh.annotations.Param;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.annotations.TearDown;

import java.io.BufferedReader;
import java.io.InputStreamReader;
import java.net.InetSocketAddress;
import java.net.SocketAddress;
import java.nio.ByteBuffer;
import java.nio.channels.DatagramChannel;
import java.nio.file.Path;

/**
 * The physical floor: a 500-byte UDP ping-pong on loopback, per hop. On one thread (two sockets,
 * the system calls alone), between two threads (a wake-up per hop), between two processes.
 */
@State(Scope.Benchmark)
public class UdpBaselineBenchmark {
    @Param({"onethread", "threads", "processes"})
    public String mode;

    private DatagramChannel a;
    private DatagramChannel b;
    private SocketAddress aAt;
    private SocketAddress bAt;
    private final ByteBuffer out = ByteBuffer.allocateDirect(500);
    private final ByteBuffer in = ByteBuffer.allocateDirect(2048);
    private Thread echo;
    private Process process;

    @Setup(Level.Trial)
    public void start() throws Exception {
        a = DatagramChannel.open().bind(new InetSocketAddress("127.0.0.1", 0));
        aAt = a.getLocalAddress();
        switch (mode) {
            case "onethread" -> {
                b = DatagramChannel.open().bind(new InetSocketAddress("127.0.0.1", 0));
                bAt = b.getLocalAddress();
            }
            case "threads" -> {
                b = DatagramChannel.open().bind(new InetSocketAddress("127.0.0.1", 0));
                bAt = b.getLocalAddress();
                echo = new Thread(() -> {
                    ByteBuffer buf = ByteBuffer.allocateDirect(2048);
                    try {
                        while (true) {
                            buf.clear();
                            SocketAddress from = b.receive(buf);
                            buf.flip();
                            b.send(buf, from);
                        }
                    } catch (Exception e) {
                        // closed
                    }
                }, "udp-echo");
                echo.setDaemon(true);
                echo.start();
            }
            default -> {
                String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
                process = new ProcessBuilder(java, "-cp", System.getProperty("java.class.path"), UdpEcho.class.getName())
                        .redirectError(ProcessBuilder.Redirect.INHERIT).start();
                String line = new BufferedReader(new InputStreamReader(process.getInputStream())).readLine();
                bAt = new InetSocketAddress("127.0.0.1", Integer.parseInt(line.substring(5)));
            }
        }
    }

    @Benchmark
    @OperationsPerInvocation(2)
    public int pingPong() throws Exception {
        out.clear();
        a.send(out, bAt);
        if (mode.equals("onethread")) {
            in.clear();
            b.receive(in);
            in.flip();
            b.send(in, aAt);
        }
        in.clear();
        a.receive(in);
        return in.position();
    }

    @TearDown(Level.Trial)
    public void stop() throws Exception {
        a.close();
        if (b != null) {
            b.close();
        }
        if (process != null) {
            process.getOutputStream().close();
            process.waitFor();
        }
    }
}
