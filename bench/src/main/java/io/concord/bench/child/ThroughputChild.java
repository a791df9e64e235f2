package io.concord.bench.child;

import io.concord.bench.support.Platforms;
import io.concord.bench.throughput.ConcordReceiver;
import io.concord.bench.throughput.Counters;
import io.concord.bench.throughput.JadeReceiver;
import io.concord.bench.throughput.UdpFloor;
import io.concord.core.agent.AgentRuntime;
import jade.core.Profile;
import jade.core.ProfileImpl;
import jade.wrapper.ContainerController;

import java.io.BufferedReader;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;

/**
 * The receiving side of a throughput run in a JVM of its own: {@code concord <R>}, {@code jade <R>
 * <main port>} (a peripheral container of the parent's JADE platform) or {@code udp <R>}. Prints
 * {@code READY} and the receivers' addresses; answers {@code COUNT} with {@code COUNT <received>};
 * exits when its input closes.
 */
public final class ThroughputChild {
    private ThroughputChild() {
    }

    public static void main(String[] args) throws Exception {
        String kind = args[0];
        int r = Integer.parseInt(args[1]);
        AutoCloseable platform;
        StringBuilder ready = new StringBuilder("READY");
        switch (kind) {
            case "concord" -> {
                AgentRuntime rt = Platforms.concord(Platforms.CONCORD_CLASS7);
                for (int i = 0; i < r; i++) {
                    ready.append(' ').append(rt.startAgent("r" + i, new ConcordReceiver()).addresses().get(0));
                }
                platform = rt;
            }
            case "jade" -> {
                jade.core.Runtime jrt = jade.core.Runtime.instance();
                jrt.setCloseVM(false);
                Profile p = new ProfileImpl();
                p.setParameter(Profile.MAIN_HOST, "127.0.0.1");
                p.setParameter(Profile.MAIN_PORT, args[2]);
                p.setParameter(Profile.LOCAL_HOST, "127.0.0.1");
                p.setParameter(Profile.CONTAINER_NAME, "receivers");
                ContainerController c = jrt.createAgentContainer(p);
                for (int i = 0; i < r; i++) {
                    c.createNewAgent("r" + i, JadeReceiver.class.getName(), new Object[0]).start();
                }
                platform = () -> c.kill();
            }
            case "udp" -> {
                UdpFloor.Receivers u = new UdpFloor.Receivers(r);
                for (int port : u.ports()) {
                    ready.append(' ').append(port);
                }
                platform = u;
            }
            default -> throw new IllegalArgumentException("concord, jade or udp, not " + kind);
        }
        System.out.println(ready);
        System.out.flush();
        BufferedReader in = new BufferedReader(new InputStreamReader(System.in, StandardCharsets.UTF_8));
        String line;
        while ((line = in.readLine()) != null) {
            if (line.equals("COUNT")) {
                System.out.println("COUNT " + Counters.RECEIVED.get());
                System.out.flush();
            }
        }
        try {
            platform.close();
        } catch (Exception e) {
            // exiting anyway
        }
        System.exit(0);
    }
}
