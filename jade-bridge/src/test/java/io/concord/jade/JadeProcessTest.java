package io.concord.jade;

import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.Performative;
import io.concord.core.agent.PortRange;
import io.concord.layers.Profile;
import io.concord.layers.SafetyStack;
import io.concord.layers.Platform;
import io.concord.layers.security.IdentityStore;
import io.concord.layers.security.PlatformKey;
import org.junit.jupiter.api.Test;

import java.io.BufferedReader;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;

import static org.junit.jupiter.api.Assertions.assertEquals;

/** The same conversations with a JADE 4.3 platform running in a separate JVM process. */
class JadeProcessTest {

    @Test
    void requestsBothWaysWithJadeInAnotherProcess() throws Exception {
        long pid = ProcessHandle.current().pid();
        String jadePlatform = "jproc" + pid;
        String concordPlatform = "cproc" + pid;
        int jadeHttp = JadeBridgeTest.freePort();
        int concordHttp = JadeBridgeTest.freePort();
        try (Platform concord = Platform.builder().name(concordPlatform).ports(PortRange.of(7791, 7799)).network(null)
                .safetyStack(SafetyStack.builder().profile(Profile.CLASS_7).platformKey(PlatformKey.random())
                        .identities(IdentityStore.ephemeral()).build())
                .gateway(() -> new HttpMtp("127.0.0.1", concordHttp)).build()) {
            concord.startAgent("echo", new JadeBridgeTest.ConcordEcho());
            JadeBridgeTest.Inbox inbox = new JadeBridgeTest.Inbox();
            concord.startAgent("inbox", inbox);
            String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
            Process jade = new ProcessBuilder(java, "-cp", System.getProperty("java.class.path"), JadeChild.class.getName(),
                    jadePlatform, Integer.toString(jadeHttp), "echo@" + concordPlatform, "http://127.0.0.1:" + concordHttp + "/acc")
                    .redirectError(ProcessBuilder.Redirect.DISCARD).start();
            try {
                BufferedReader out = new BufferedReader(new InputStreamReader(jade.getInputStream(), StandardCharsets.UTF_8));
                CompletableFuture<String> answer = new CompletableFuture<>();
                CompletableFuture<Void> ready = new CompletableFuture<>();
                Thread reader = new Thread(() -> {
                    try {
                        String l;
                        while ((l = out.readLine()) != null) {
                            if (l.equals("READY")) {
                                ready.complete(null);
                            } else if (l.startsWith("ANSWER ")) {
                                answer.complete(l.substring(7));
                            }
                        }
                    } catch (java.io.IOException ignored) {
                        // the child ended
                    }
                });
                reader.setDaemon(true);
                reader.start();
                ready.get(60, TimeUnit.SECONDS);
                // JADE (other process) to Concord.
                assertEquals("INFORM echo:from-jade-process", answer.get(60, TimeUnit.SECONDS));
                // Concord to JADE (other process), by its HTTP address.
                AclMessage req = new AclMessage(Performative.REQUEST);
                req.addReceiver(new AID("jecho@" + jadePlatform, "http://127.0.0.1:" + jadeHttp + "/acc"));
                req.setContent("from-concord");
                req.setConversationId("pc1");
                inbox.send(req);
                long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(60);
                AclMessage got = null;
                while (got == null && System.nanoTime() < end) {
                    AclMessage m = inbox.got.poll(100, TimeUnit.MILLISECONDS);
                    if (m != null && "pc1".equals(m.getConversationId())) {
                        got = m;
                    }
                }
                assertEquals("jade-echo:from-concord", got == null ? null : got.getContent());
            } finally {
                jade.getOutputStream().close();
                if (!jade.waitFor(10, TimeUnit.SECONDS)) {
                    jade.destroyForcibly();
                }
            }
        }
    }
}
