package io.concord.dist;

import org.junit.jupiter.api.Test;

import java.io.BufferedReader;
import java.io.File;
import java.io.IOException;
import java.io.InputStreamReader;
import java.net.ServerSocket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;

import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

/**
 * The runnable jar as a JADE user runs it, in separate processes, over HTTP on 127.0.0.1: Concord
 * started by {@code java -jar concord.jar} with the shipped annex agents, and JADE 4.3 started by
 * {@code jade.Boot} with the README's command. JADE's annex buyer, which knows nothing of Concord,
 * finds the Concord sellers in its own DF (mirrored by ConcordDfMirror) and buys from the
 * cheapest; Concord's buyer buys from JADE's annex seller; Concord's chain runs its rounds.
 * Runs after {@code package}, in the integration-test phase ({@code mvn verify}).
 */
class JadeEndToEndTest {

    /** One child process and every line it printed. */
    static final class Child implements AutoCloseable {
        final String name;
        final Process process;
        final List<String> lines = Collections.synchronizedList(new ArrayList<>());
        private final List<Object[]> waits = Collections.synchronizedList(new ArrayList<>());

        Child(String name, List<String> command) throws IOException {
            this.name = name;
            this.process = new ProcessBuilder(command).redirectErrorStream(true).start();
            Thread t = new Thread(() -> {
                try (BufferedReader r = new BufferedReader(new InputStreamReader(process.getInputStream(), StandardCharsets.UTF_8))) {
                    String l;
                    while ((l = r.readLine()) != null) {
                        lines.add(l);
                        synchronized (waits) {
                            for (Object[] w : waits) {
                                if (l.contains((String) w[0])) {
                                    @SuppressWarnings("unchecked")
                                    CompletableFuture<String> f = (CompletableFuture<String>) w[1];
                                    f.complete(l);
                                }
                            }
                        }
                    }
                } catch (IOException ignored) {
                    // the process ended
                }
            }, name + "-out");
            t.setDaemon(true);
            t.start();
        }

        /** A future completed by the first line containing the text (printed already or later). */
        CompletableFuture<String> line(String text) {
            CompletableFuture<String> f = new CompletableFuture<>();
            synchronized (waits) {
                synchronized (lines) {
                    for (String l : lines) {
                        if (l.contains(text)) {
                            f.complete(l);
                        }
                    }
                }
                waits.add(new Object[]{text, f});
            }
            return f;
        }

        String tail() {
            synchronized (lines) {
                return name + " printed:\n  " + String.join("\n  ", lines.subList(Math.max(0, lines.size() - 60), lines.size()));
            }
        }

        @Override
        public void close() {
            process.destroy();
            try {
                if (!process.waitFor(10, TimeUnit.SECONDS)) {
                    process.destroyForcibly();
                }
            } catch (InterruptedException e) {
                process.destroyForcibly();
                Thread.currentThread().interrupt();
            }
        }
    }

    static int freePort() throws IOException {
        try (ServerSocket s = new ServerSocket(0)) {
            return s.getLocalPort();
        }
    }

    @Test
    void aJadeBookBuyerBuysFromConcordSellersStartedFromTheRunnableJar() throws Exception {
        Path jar = Path.of(System.getProperty("basedir", "."), "target", "concord.jar").toAbsolutePath();
        assertTrue(Files.isRegularFile(jar), "the runnable jar is built by package: " + jar);
        String javaBin = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        String jadeJar = null;
        for (String e : System.getProperty("java.class.path").split(File.pathSeparator)) {
            if (e.contains("jade-4.3")) {
                jadeJar = e;
            }
        }
        assertTrue(jadeJar != null, "JADE 4.3 is on the test class path");
        String testClasses = Path.of(System.getProperty("basedir", "."), "target", "test-classes").toAbsolutePath().toString();
        int concordHttp = freePort();
        int jadeHttp = freePort();
        int jadeMain = freePort();
        String concordAcc = "http://127.0.0.1:" + concordHttp + "/acc";
        String jadeAcc = "http://127.0.0.1:" + jadeHttp + "/acc";
        Path home = Files.createTempDirectory("concord-e2e");

        // Concord, exactly as the README says, with the shipped annex agents.
        List<String> concordCmd = List.of(javaBin, "-Duser.home=" + home, "-jar", jar.toString(), "-name", "concord",
                "-ports", "7861-7879", "-http", Integer.toString(concordHttp), "-agents",
                "s1:io.concord.examples.BookSeller(40);s2:io.concord.examples.BookSeller(30);"
                        + "buyer:io.concord.examples.BookBuyer(jseller@jadeplat=" + jadeAcc + ");"
                        + "c1:io.concord.examples.ChainLink(c2,5);c2:io.concord.examples.ChainLink(c3);"
                        + "c3:io.concord.examples.ChainLink(c1)");
        // JADE 4.3, with the README's command: its HTTP MTP, the SAX parser fix, the DF mirror, and
        // the annex agents written for JADE.
        List<String> jadeCmd = List.of(javaBin, "-cp", jadeJar + File.pathSeparator + jar + File.pathSeparator
                        + testClasses, "jade.Boot", "-name", "jadeplat", "-host", "127.0.0.1", "-port", Integer.toString(jadeMain),
                "-detect-main", "false", "-mtps", "jade.mtp.http.MessageTransportProtocol(" + jadeAcc + ")",
                "-jade_mtp_http_parser", "io.concord.jade.JadeSaxParser", "-agents",
                "mirror:io.concord.jade.ConcordDfMirror(concord," + concordAcc + ",200);"
                        + "jseller:io.concord.dist.JadeAnnexSeller(20);jbuyer:io.concord.dist.JadeAnnexBuyer(2)");
        try (Child concord = new Child("concord", concordCmd); Child jade = new Child("jade", jadeCmd)) {
            try {
                String acc = concord.line("JADE bridge:").get(60, TimeUnit.SECONDS);
                assertTrue(acc.contains(concordAcc) && acc.contains("<name>@concord"), acc);
                String jadeBought = jade.line("jbuyer: AGREE from").get(90, TimeUnit.SECONDS);
                assertTrue(jadeBought.contains("s2@concord") && jadeBought.contains("$30"),
                        "JADE's buyer bought from the cheapest Concord seller: " + jadeBought);
                String concordBought = concord.line("buyer: AGREE from").get(90, TimeUnit.SECONDS);
                assertTrue(concordBought.contains("jseller@jadeplat") && concordBought.contains("$20"),
                        "Concord's buyer bought from JADE's seller: " + concordBought);
                String chain = concord.line("chain: 5 rounds").get(60, TimeUnit.SECONDS);
                assertTrue(chain.startsWith("c1: chain: 5 rounds"), chain);
            } catch (TimeoutException | AssertionError e) {
                fail("the end-to-end run did not finish: " + e + "\n" + concord.tail() + "\n" + jade.tail());
            }
        }
    }
}
