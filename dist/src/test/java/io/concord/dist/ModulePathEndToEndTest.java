package io.concord.dist;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import javax.tools.JavaCompiler;
import javax.tools.ToolProvider;
import java.io.BufferedReader;
import java.io.ByteArrayOutputStream;
import java.io.File;
import java.io.IOException;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.stream.Collectors;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * Concord on the module path, as a modular application uses it: {@code concord-core} is a named
 * module (its {@code module-info}), the other jars automatic modules. The agents trade over the
 * safety stack, which core finds with {@code ServiceLoader}; an application module reaches core's
 * API and cannot reach its {@code internal} packages. Runs after {@code package}: it needs the jars.
 */
class ModulePathEndToEndTest {

    /** The jars of these artifacts, from this test's class path (the reactor's packaged jars). */
    private static String modulePath(String... artifacts) {
        List<String> found = new ArrayList<>();
        List<String> entries = Arrays.asList(System.getProperty("java.class.path").split(File.pathSeparator));
        for (String a : artifacts) {
            String jar = entries.stream().filter(e -> Path.of(e).getFileName().toString().startsWith(a + "-") && e.endsWith(".jar"))
                    .findFirst().orElseThrow(() -> new IllegalStateException("no jar of " + a + " on the class path " + entries
                            + " (run with mvn verify, which packages the modules first)"));
            found.add(jar);
        }
        return String.join(File.pathSeparator, found);
    }

    @Test
    void annexAgentsTradeOnTheModulePathOverTheSafetyStack() throws Exception {
        String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        String path = modulePath("concord-core", "concord-layers", "concord-examples", "slf4j-api", "slf4j-simple", "bcprov-jdk18on");
        Process p = new ProcessBuilder(java, "-p", path, "--add-modules", "ALL-MODULE-PATH",
                "-m", "io.concord.layers/io.concord.layers.Boot", "-name", "modules",
                "-agents", "s1:io.concord.examples.BookSeller(40);buyer:io.concord.examples.BookBuyer(s1,rounds=1)")
                .redirectErrorStream(true).start();
        List<String> lines = new ArrayList<>();
        try (BufferedReader out = new BufferedReader(new InputStreamReader(p.getInputStream(), StandardCharsets.UTF_8))) {
            String line;
            while ((line = out.readLine()) != null) {
                lines.add(line);
                if (line.contains("bought 1 book ")) {
                    break;
                }
            }
        } finally {
            p.destroy();
            if (!p.waitFor(30, TimeUnit.SECONDS)) {
                p.destroyForcibly();
            }
        }
        String all = String.join("\n", lines);
        assertTrue(all.contains("buyer: bought 1 book in 1 attempt"), "the trade did not finish on the module path:\n" + all);
        assertFalse(all.contains("no safety layers"), "core did not find the safety stack on the module path:\n" + all);
    }

    @Test
    void anApplicationModuleReachesTheApiButNotTheInternals(@TempDir Path dir) throws IOException {
        String path = modulePath("concord-core", "slf4j-api");
        String api = "import io.concord.core.time.Clock;\n"
                + "public class Main { public static void main(String[] a) { System.out.println(Clock.system().nanoTime()); } }\n";
        assertEquals("", compile(dir.resolve("api"), path, api), "an application module must compile against core's API");

        String internal = "import io.concord.core.time.internal.LoopLimits;\n"
                + "public class Main { public static void main(String[] a) { System.out.println(new LoopLimits()); } }\n";
        String errors = compile(dir.resolve("internal"), path, internal);
        assertNotEquals("", errors, "an application module compiled against core's internal package");
        assertTrue(errors.contains("io.concord.core.time.internal"), errors);
    }

    /** Compiles module {@code app} (requires io.concord.core) with this class; returns the errors, or "". */
    private static String compile(Path dir, String modulePath, String mainSource) throws IOException {
        Path src = dir.resolve("src");
        Files.createDirectories(src.resolve("app"));
        Files.writeString(src.resolve("module-info.java"), "module app { requires io.concord.core; }\n");
        Files.writeString(src.resolve("app").resolve("Main.java"), "package app;\n" + mainSource);
        JavaCompiler javac = ToolProvider.getSystemJavaCompiler();
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        List<String> args = new ArrayList<>(List.of("-p", modulePath, "-d", dir.resolve("out").toString(),
                src.resolve("module-info.java").toString(), src.resolve("app").resolve("Main.java").toString()));
        int rc = javac.run(null, null, err, args.toArray(String[]::new));
        String text = err.toString(StandardCharsets.UTF_8);
        return rc == 0 ? "" : text.lines().filter(l -> l.contains("error")).collect(Collectors.joining("\n"));
    }
}
