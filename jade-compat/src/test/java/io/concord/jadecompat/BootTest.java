package io.concord.jadecompat;

import jade.core.Agent;
import org.junit.jupiter.api.Test;

import java.io.File;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** {@code jade.Boot} with JADE's command line, started in a process of its own as a JADE user starts it. */
class BootTest {

    /** Says who it is and what it was given, then ends the JVM. */
    public static class Hello extends Agent {
        @Override
        protected void setup() {
            List<String> args = new ArrayList<>();
            for (Object a : getArguments()) {
                args.add(String.valueOf(a));
            }
            System.out.println("hello from " + getName() + " with " + args);
            if (getLocalName().startsWith("last")) {
                try {
                    Thread.sleep(500); // lets the agents before it print
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                }
                System.exit(0);
            }
        }
    }

    @Test
    void bootStartsTheAgentsOfTheCommandLineAndNamesWhatItIgnores() throws Exception {
        int port = CorpusPorts.freeBase();
        String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        List<String> cp = new ArrayList<>();
        for (String e : System.getProperty("java.class.path").split(File.pathSeparator)) {
            if (!e.contains("ingenias")) {
                cp.add(e);
            }
        }
        Process p = new ProcessBuilder(java, "-cp", String.join(File.pathSeparator, cp), "jade.Boot",
                "-gui", "-name", "bootplat", "-host", "127.0.0.1", "-port", Integer.toString(port),
                "-services", "jade.core.event.NotificationService", "-mtps", "jade.mtp.http.MessageTransportProtocol",
                "-agents", "greeter:" + Hello.class.getName() + "(one, two);last one:" + Hello.class.getName() + "(\"x, y\" , z)")
                .redirectErrorStream(false).start();
        p.getOutputStream().close();
        assertTrue(p.waitFor(60, TimeUnit.SECONDS), "jade.Boot did not end");
        String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertEquals(0, p.exitValue(), out);
        assertTrue(out.contains("hello from greeter@bootplat with [one, two]"), out);
        // JADE's Boot (4.3.3, tried): a name may hold a space; arguments split at every comma, trimmed, quotes kept
        assertTrue(out.contains("hello from last one@bootplat with [\"x, y\", z]"), out);
        assertTrue(out.contains("jade.Boot: -services is ignored"), out);
        assertTrue(out.contains("jade.Boot: -mtps is ignored"), out);
        assertTrue(out.contains("-gui: Concord's console is not on the class path"), out);
    }
}
