package io.concord.core.net;

import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.Performative;
import io.concord.core.agent.Agent;
import io.concord.core.agent.AgentRuntime;
import io.concord.core.agent.LambdaAgent;
import io.concord.core.proto.Conversations;
import io.concord.core.proto.ProtocolException;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

import java.io.BufferedReader;
import java.io.File;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** The interaction protocols over real UDP between this JVM and another JVM process. */
class TwoProcessUdpTest {
    private static Process remote;
    private static final Map<String, AID> REMOTE_AGENTS = new HashMap<>();
    private static AgentRuntime rt;
    private static Agent client;

    @BeforeAll
    static void startRemoteJvm() throws Exception {
        String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        // core is a named module: its tests run with core (and this test's classes) on the module
        // path, the rest on the class path; the other JVM takes both on its class path
        String modules = System.getProperty("jdk.module.path");
        String cp = System.getProperty("java.class.path") + (modules == null ? "" : File.pathSeparator + modules);
        remote = new ProcessBuilder(java, "-cp", cp, RemoteResponders.class.getName())
                .redirectError(ProcessBuilder.Redirect.INHERIT).start();
        BufferedReader out = new BufferedReader(new InputStreamReader(remote.getInputStream(), StandardCharsets.UTF_8));
        String line;
        while ((line = out.readLine()) != null && !line.equals("ALL READY")) {
            String[] p = line.split(" ");
            if (p.length == 3 && p[0].equals("READY")) {
                REMOTE_AGENTS.put(p[1], new AID(p[1] + "@remote", p[2]));
            }
        }
        if (line == null) {
            throw new IllegalStateException("the remote JVM ended before it was ready; exit " + remote.waitFor());
        }
        rt = AgentRuntime.builder().platformName("local").build().start();
        LambdaAgent c = new LambdaAgent(a -> { });
        rt.startAgent("client", c);
        client = c;
    }

    @AfterAll
    static void stop() throws Exception {
        if (rt != null) {
            rt.close();
        }
        if (remote != null) {
            remote.getOutputStream().close();
            if (!remote.waitFor(10, TimeUnit.SECONDS)) {
                remote.destroyForcibly();
            }
        }
    }

    private static <T> T onLoop(java.util.function.Supplier<CompletableFuture<T>> start) throws Exception {
        CompletableFuture<T> result = new CompletableFuture<>();
        rt.execute(() -> start.get().whenComplete((v, e) -> {
            if (e != null) {
                result.completeExceptionally(e);
            } else {
                result.complete(v);
            }
        }));
        return result.get(20, TimeUnit.SECONDS);
    }

    @Test
    void theRemoteAgentsRunInAnotherProcess() {
        assertTrue(remote.isAlive());
        assertTrue(remote.pid() != ProcessHandle.current().pid());
        assertEquals(5, REMOTE_AGENTS.size());
    }

    @Test
    void requestAcrossProcesses() throws Exception {
        AclMessage inform = onLoop(() -> Conversations.request(client,
                new AclMessage(Performative.REQUEST).addReceiver(REMOTE_AGENTS.get("echo")).setContent("over the wire")));
        assertEquals("echo over the wire", inform.getContent());
        assertEquals("echo@remote", inform.getSender().name());
    }

    @Test
    void aRefusalAcrossProcesses() {
        ExecutionException e = assertThrows(ExecutionException.class, () -> onLoop(() -> Conversations.request(client,
                new AclMessage(Performative.REQUEST).addReceiver(REMOTE_AGENTS.get("echo")).setContent("refuse me"))));
        ProtocolException pe = assertInstanceOf(ProtocolException.class, e.getCause());
        assertEquals(ProtocolException.Reason.REFUSED, pe.reason());
    }

    @Test
    void queryAcrossProcesses() throws Exception {
        AclMessage inform = onLoop(() -> Conversations.request(client,
                new AclMessage(Performative.QUERY_REF).addReceiver(REMOTE_AGENTS.get("oracle")).setContent("(answer)")));
        assertEquals("(= (answer) 42)", inform.getContent());
    }

    @Test
    void contractNetAcrossProcesses() throws Exception {
        AclMessage cfp = new AclMessage(Performative.CFP).addReceiver(REMOTE_AGENTS.get("seller17"))
                .addReceiver(REMOTE_AGENTS.get("seller12")).setContent("book");
        Conversations.ContractNetOutcome out = onLoop(() -> Conversations.contractNet(client, cfp,
                ps -> ps.stream().min(Comparator.comparingInt(p -> Integer.parseInt(p.getContent()))).orElse(null)));
        assertEquals("sold at 12", out.result().getContent());
    }

    @Test
    void subscribeAcrossProcesses() throws Exception {
        List<String> seen = new ArrayList<>();
        CompletableFuture<List<String>> three = new CompletableFuture<>();
        onLoop(() -> Conversations.subscribe(client,
                new AclMessage(Performative.SUBSCRIBE).addReceiver(REMOTE_AGENTS.get("door")).setContent("(position)"),
                n -> {
                    seen.add(n.getContent());
                    if (seen.size() == 3) {
                        three.complete(new ArrayList<>(seen));
                    }
                }).agreed());
        assertEquals(List.of("opening", "open", "closing"), three.get(20, TimeUnit.SECONDS));
    }

    @Test
    void anUnknownRemoteNameFailsFast() {
        ExecutionException e = assertThrows(ExecutionException.class, () -> onLoop(() -> Conversations.request(client,
                new AclMessage(Performative.REQUEST).addReceiver(new AID("ghost@remote")).setContent("x"))));
        assertEquals(ProtocolException.Reason.FAILED, ((ProtocolException) e.getCause()).reason());
    }

}
