package io.concord.layers;

import io.concord.core.agent.Agent;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

class BootTest {

    /** Records its arguments. */
    public static final class Recorder extends Agent {
        static volatile Object[] seen;

        @Override
        protected void setup() {
            seen = getArguments();
        }
    }

    @Test
    void parsesAgentSpecsLikeJade() {
        List<Boot.AgentSpec> specs = Boot.parseAgents("seller1:org.example.Seller(42, The Art);buyer:org.example.Buyer ; x:a.B()");
        assertEquals(List.of(new Boot.AgentSpec("seller1", "org.example.Seller", List.of("42", "The Art")),
                new Boot.AgentSpec("buyer", "org.example.Buyer", List.of()),
                new Boot.AgentSpec("x", "a.B", List.of())), specs);
    }

    @Test
    void badSpecsSayWhatIsWrong() {
        assertTrue(assertThrows(Boot.BootException.class, () -> Boot.parseAgents("seller1"))
                .getMessage().contains("name:class"));
        assertTrue(assertThrows(Boot.BootException.class, () -> Boot.parseAgents("a:b.C(1"))
                .getMessage().contains("unclosed '('"));
        assertTrue(assertThrows(Boot.BootException.class, () -> Boot.parseAgents("a:b.C(1))"))
                .getMessage().contains("unmatched ')'"));
        assertTrue(assertThrows(Boot.BootException.class, () -> Boot.parseAgents("a:not a class"))
                .getMessage().contains("not a Java class name"));
    }

    @Test
    void badOptionsAndClassesSayWhatToDo() {
        PrintStream out = new PrintStream(new ByteArrayOutputStream(), true, StandardCharsets.UTF_8);
        assertTrue(assertThrows(Boot.BootException.class, () -> Boot.start(new String[]{"-nmae", "x"}, out))
                .getMessage().contains("unknown option '-nmae'"));
        assertTrue(assertThrows(Boot.BootException.class, () -> Boot.start(new String[]{"-profile", "class9"}, out))
                .getMessage().contains("use class7 (default), class3 or closed"));
        assertTrue(assertThrows(Boot.BootException.class, () -> Boot.start(new String[]{"-ports", "7001-x"}, out))
                .getMessage().contains("7001-7200"));
        assertTrue(assertThrows(Boot.BootException.class,
                () -> Boot.start(new String[]{"-agents", "a:org.example.Missing"}, out))
                .getMessage().contains("not on the class path"));
        assertTrue(assertThrows(Boot.BootException.class,
                () -> Boot.start(new String[]{"-agents", "a:java.lang.String"}, out))
                .getMessage().contains("does not extend"));
        // The layers module alone has no JADE bridge on its class path.
        assertTrue(assertThrows(Boot.BootException.class, () -> Boot.start(new String[]{"-http", "7779"}, out))
                .getMessage().contains("add concord-jade-bridge to the class path"));
        assertTrue(assertThrows(Boot.BootException.class, () -> Boot.start(new String[]{"-http", "x:y"}, out))
                .getMessage().contains("-http is written port or host:port"));
        assertTrue(assertThrows(Boot.BootException.class, () -> Boot.start(new String[]{"-key", "no/such.key"}, out))
                .getMessage().contains("-key: the platform key file no/such.key does not exist"));
    }

    @Test
    void anOptionGivenTwiceOrAServiceThatCannotBeExposedStopsBootWithWhy() {
        PrintStream out = new PrintStream(new ByteArrayOutputStream(), true, StandardCharsets.UTF_8);
        assertTrue(assertThrows(Boot.BootException.class, () -> Boot.start(new String[]{"-name", "a", "-name", "b"}, out))
                .getMessage().contains("-name is given twice"));
        assertTrue(assertThrows(Boot.BootException.class, () -> Boot.start(new String[]{"-http-expose", "resume", "-agents",
                "x:io.concord.testkit.EchoAgent"}, out)).getMessage().contains("-http-expose: resume cannot be exposed"));
    }

    @Test
    void aPlatformWithItsOwnKeyCannotBeReachedWithTheUsersKey(@TempDir Path dir) throws Exception {
        Path own = dir.resolve("own.key");
        Files.writeString(own, "ab".repeat(32));
        Files.setPosixFilePermissions(own, java.nio.file.attribute.PosixFilePermissions.fromString("rw-------"));
        PrintStream out = new PrintStream(new ByteArrayOutputStream(), true, StandardCharsets.UTF_8);
        String name = "keyed" + ProcessHandle.current().pid();
        try (Platform p = Boot.start(new String[]{"-name", name, "-ports", "7701-7720", "-key", own.toString(),
                "-agents", "r:" + Recorder.class.getName()}, out)) {
            java.util.List<io.concord.core.layer.Layer> layers = p.runtime().layers(new io.concord.core.acl.AID("r@" + name));
            io.concord.layers.security.SecurityLayer sec = layers.stream()
                    .filter(l -> l instanceof io.concord.layers.security.SecurityLayer)
                    .map(l -> (io.concord.layers.security.SecurityLayer) l).findFirst().orElseThrow();
            assertEquals(own.toString(), sec.platformKeyOrigin(), "the agent seals with the key -key names");
        }
    }

    @Test
    void aConfigurationFileAndTheCommandLineCombine(@TempDir Path dir) throws Exception {
        Path conf = dir.resolve("platform.properties");
        Files.writeString(conf, "name=confplat\nports=7601-7650\nprofile=closed\n");
        Map<String, String> s = Boot.settings(new String[]{"-conf", conf.toString(), "-ports", "7651-7700"});
        assertEquals("confplat", s.get("name"));
        assertEquals("7651-7700", s.get("ports"));
        assertEquals("closed", s.get("profile"));
        Files.writeString(conf, "nmae=x\n");
        assertTrue(assertThrows(Boot.BootException.class, () -> Boot.settings(new String[]{"-conf", conf.toString()}))
                .getMessage().contains("unknown setting 'nmae'"));
    }

    @Test
    void startsTheAgentsWithTheirArguments() {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        PrintStream out = new PrintStream(bytes, true, StandardCharsets.UTF_8);
        String name = "boot" + ProcessHandle.current().pid();
        try (Platform p = Boot.start(new String[]{"-name", name, "-ports", "7651-7700", "-profile", "closed",
                "-agents", "r:" + Recorder.class.getName() + "(1,two)"}, out)) {
            assertEquals(name, p.name());
            assertArrayEquals(new Object[]{"1", "two"}, Recorder.seen);
            String printed = bytes.toString(StandardCharsets.UTF_8);
            assertTrue(printed.startsWith("started r@" + name + " at udp://127.0.0.1:76"), printed);
        }
    }
}
