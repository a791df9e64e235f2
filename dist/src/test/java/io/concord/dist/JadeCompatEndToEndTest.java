package io.concord.dist;

import org.junit.jupiter.api.Test;

import java.io.File;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * concord-jade inside the runnable jar: {@code java -cp concord.jar:app jade.Boot -agents ...} runs a
 * JADE agent on Concord; with JADE's own jar on the class path after it, the start-up says so.
 * Runs after {@code package}: it needs the jar.
 */
class JadeCompatEndToEndTest {

    private static String run(String classPath) throws Exception {
        String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        Path home = Files.createTempDirectory("concord-jade-e2e");
        List<String> cmd = List.of(java, "-Duser.home=" + home, "-cp", classPath, "jade.Boot", "-name", "boot",
                "-host", "127.0.0.1", "-port", Integer.toString(JadeEndToEndTest.freePort()),
                "-agents", "greeter:io.concord.dist.JadeCompatAgent(x,y)");
        Process p = new ProcessBuilder(cmd).redirectErrorStream(true).start();
        p.getOutputStream().close();
        String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertTrue(p.waitFor(60, TimeUnit.SECONDS), "jade.Boot did not end: " + out);
        assertEquals(0, p.exitValue(), out);
        return out;
    }

    private static Path jar() {
        Path jar = Path.of(System.getProperty("basedir", "."), "target", "concord.jar").toAbsolutePath();
        assertTrue(Files.isRegularFile(jar), "the runnable jar is built by package: " + jar);
        return jar;
    }

    private static String testClasses() {
        return Path.of(System.getProperty("basedir", "."), "target", "test-classes").toAbsolutePath().toString();
    }

    @Test
    void aJadeAgentRunsFromTheRunnableJarWithJadesBoot() throws Exception {
        String out = run(jar() + File.pathSeparator + testClasses());
        assertTrue(out.contains("jade agent greeter@boot with 2 arguments"), out);
        assertFalse(out.contains("JADE's own jar is on the class path too"), out);
    }

    @Test
    void withJadesOwnJarBesideItTheStartUpSaysSo() throws Exception {
        String jadeJar = null;
        for (String e : System.getProperty("java.class.path").split(File.pathSeparator)) {
            if (e.contains("jade-4.3")) {
                jadeJar = e;
            }
        }
        assertTrue(jadeJar != null, "JADE 4.3 is on the test class path");
        List<String> cp = new ArrayList<>(List.of(jar().toString(), jadeJar, testClasses()));
        String out = run(String.join(File.pathSeparator, cp));
        assertTrue(out.contains("JADE's own jar is on the class path too"), out);
    }
}
