package io.concord.jadecompat;

import jade.core.Agent;
import jade.core.Profile;
import jade.core.ProfileImpl;
import jade.wrapper.AgentContainer;
import jade.wrapper.AgentController;
import org.junit.jupiter.api.Test;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * JADE's tool agents under their JADE class names: each starts, says once on standard error
 * that it is a JADE window concord-jade does not have and what Concord offers instead (the web
 * console), ends itself, and the launcher's next agent starts and runs.
 */
class ToolStandInTest {
    private static final String[] TOOLS = {"jade.tools.rma.rma", "jade.tools.sniffer.Sniffer", "jade.tools.DummyAgent.DummyAgent",
        "jade.tools.introspector.Introspector"};

    @Test
    void eachToolSaysOnceWhatConcordOffersAndEndsAndTheLauncherGoesOn() throws Exception {
        Profile p = new ProfileImpl();
        p.setParameter(Profile.LOCAL_HOST, "127.0.0.1");
        p.setParameter(Profile.LOCAL_PORT, Integer.toString(CorpusPorts.freeBase()));
        p.setParameter(Profile.PLATFORM_ID, "tools");
        AgentContainer c = jade.core.Runtime.instance().createMainContainer(p);
        PrintStream err = System.err;
        ByteArrayOutputStream captured = new ByteArrayOutputStream();
        System.setErr(new PrintStream(captured, true, StandardCharsets.UTF_8));
        CountDownLatch after = new CountDownLatch(1);
        try {
            for (int i = 0; i < TOOLS.length; i++) {
                AgentController tool = c.createNewAgent("tool" + i, TOOLS[i], null);
                tool.start();
                long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(10);
                while (!tool.getState().getName().equals("Deleted") && System.nanoTime() < deadline) {
                    Thread.sleep(10);
                }
                assertEquals("Deleted", tool.getState().getName(), TOOLS[i] + " did not end by itself");
            }
            c.acceptNewAgent("after-the-tools", new Agent() {
                @Override
                protected void setup() {
                    after.countDown();
                }
            }).start();
            assertTrue(after.await(10, TimeUnit.SECONDS), "the agent started after the tools did not run");
        } finally {
            System.setErr(err);
        }
        String text = captured.toString(StandardCharsets.UTF_8);
        for (int i = 0; i < TOOLS.length; i++) {
            String said = "concord-jade: tool" + i + " is JADE's ";
            assertEquals(1, text.split(java.util.regex.Pattern.quote(said), -1).length - 1,
                    TOOLS[i] + " must say once what it is; standard error was:\n" + text);
            assertTrue(text.contains(TOOLS[i]), "the notice names the JADE class " + TOOLS[i] + ":\n" + text);
        }
        assertTrue(text.contains("web console") && text.contains("-gui") && text.contains("-console [host:]port"),
                "the notice says what Concord offers instead:\n" + text);
    }
}
