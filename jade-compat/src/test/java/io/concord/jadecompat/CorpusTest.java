package io.concord.jadecompat;

import org.junit.jupiter.api.DynamicTest;
import org.junit.jupiter.api.TestFactory;

import javax.tools.Diagnostic;
import javax.tools.DiagnosticCollector;
import javax.tools.JavaCompiler;
import javax.tools.JavaFileObject;
import javax.tools.StandardJavaFileManager;
import javax.tools.ToolProvider;
import java.io.File;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.stream.Collectors;
import java.util.stream.Stream;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

/**
 * The heart: each program of {@code src/test/corpus/<name>/}, written against JADE 4.3's
 * API as its tutorials teach it, is compiled twice (against JADE's jar, and against concord-jade)
 * and run twice, each in a JVM of its own; what it prints on standard output must be the same,
 * line for line. A program that needs a change to run on Concord is a failure of concord-jade.
 */
class CorpusTest {
    private static final long RUN_TIMEOUT_S = 90;

    @TestFactory
    Stream<DynamicTest> eachProgramPrintsTheSameOnJadeAndOnConcord() throws IOException {
        Path corpus = Path.of(System.getProperty("corpus.dir", "src/test/corpus"));
        List<Path> programs;
        try (Stream<Path> s = Files.list(corpus)) {
            programs = s.filter(Files::isDirectory).sorted().collect(Collectors.toList());
        }
        assertTrue(programs.size() >= 10, "the corpus has " + programs.size() + " programs; the issue asks for at least 10 here");
        String only = System.getProperty("corpus.only");
        // -Dcorpus.only=a,b runs those programs only
        List<String> chosen = only == null ? null : List.of(only.split(","));
        return programs.stream().filter(p -> chosen == null || chosen.contains(p.getFileName().toString()))
                .map(p -> DynamicTest.dynamicTest(p.getFileName().toString(), () -> runBothWays(p)));
    }

    private static void runBothWays(Path program) throws Exception {
        Path jadeJar = Path.of(System.getProperty("jade.jar"));
        assertTrue(Files.isRegularFile(jadeJar), "JADE's jar is not at " + jadeJar);
        Path work = Files.createTempDirectory("corpus-" + program.getFileName());
        Path jadeClasses = work.resolve("jade-classes");
        Path concordClasses = work.resolve("concord-classes");
        compile(program, List.of(jadeJar.toString()), jadeClasses);
        compile(program, List.of(compatClasses()), concordClasses);

        int port = freePort();
        Run jade = run(work.resolve("jade-run"), jadeClasses + File.pathSeparator + jadeJar, port);
        String name = program.getFileName().toString();
        assertEquals(0, jade.exit, name + ": on JADE the program must end by itself with status 0; stderr:\n" + jade.errTail());
        assertFalse(jade.out.isEmpty(), name + ": the program printed nothing on JADE");

        Run concord = run(work.resolve("concord-run"), concordClasses + File.pathSeparator + concordClassPath(), freePort());
        assertEquals(String.join("\n", jade.out), String.join("\n", concord.out),
                name + ": standard output differs between JADE (expected) and Concord (actual); Concord's stderr:\n" + concord.errTail());
        assertEquals(0, concord.exit, name + ": on Concord the program must end by itself with status 0; stderr:\n" + concord.errTail());
        deleteTree(work); // kept when the program fails, to look at
    }

    private static void deleteTree(Path dir) throws IOException {
        try (Stream<Path> s = Files.walk(dir)) {
            for (Path p : s.sorted(java.util.Comparator.reverseOrder()).collect(Collectors.toList())) {
                Files.deleteIfExists(p);
            }
        }
    }

    private record Run(int exit, List<String> out, List<String> err) {
        String errTail() {
            return String.join("\n", err.subList(Math.max(0, err.size() - 40), err.size()));
        }
    }

    private static Run run(Path dir, String classPath, int port) throws Exception {
        Files.createDirectories(dir);
        Path out = dir.resolve("stdout.txt");
        Path err = dir.resolve("stderr.txt");
        String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        // A short program: the client compiler alone and the serial collector start it sooner
        // (the corpus is 110 JVMs a build), and change nothing of what it prints.
        Process p = new ProcessBuilder(java, "-XX:TieredStopAtLevel=1", "-XX:+UseSerialGC", "-Xshare:auto", "-cp", classPath,
                "-Djava.net.preferIPv4Stack=true", "Main", Integer.toString(port))
                .directory(dir.toFile()).redirectOutput(out.toFile()).redirectError(err.toFile()).start();
        if (!p.waitFor(RUN_TIMEOUT_S, TimeUnit.SECONDS)) {
            p.descendants().forEach(ProcessHandle::destroyForcibly);
            p.destroyForcibly();
            p.waitFor(10, TimeUnit.SECONDS);
            fail("did not end within " + RUN_TIMEOUT_S + " s (class path " + classPath + "); stdout:\n"
                    + Files.readString(out) + "\nstderr:\n" + tail(Files.readAllLines(err)));
        }
        List<String> printed = new ArrayList<>();
        for (String line : Files.readAllLines(out, StandardCharsets.UTF_8)) {
            if (!isJadeRuntimeNoise(line)) {
                printed.add(line);
            }
        }
        return new Run(p.exitValue(), printed, Files.readAllLines(err, StandardCharsets.UTF_8));
    }

    /**
     * JADE's own lines on standard output: when a program calls System.exit, JADE's shutdown hook
     * may print that an agent did not stop at once; an agent woken from doWait may print its
     * state; an agent killed by an exception is announced. They are JADE's runtime talking, not the program; they come and go from run to run.
     */
    static boolean isJadeRuntimeNoise(String line) {
        return line.startsWith("*** Warning: Agent ") && line.endsWith(" did not terminate when requested to do so.")
                || line.equals("*** Second interrupt issued.") || line.matches("State was \\d+")
                || line.startsWith("ERROR: Agent ") && line.endsWith(" died without being properly terminated !!!");
    }

    private static String tail(List<String> lines) {
        return String.join("\n", lines.subList(Math.max(0, lines.size() - 40), lines.size()));
    }

    private static void compile(Path program, List<String> classPath, Path out) throws IOException {
        Files.createDirectories(out);
        JavaCompiler javac = ToolProvider.getSystemJavaCompiler();
        DiagnosticCollector<JavaFileObject> diagnostics = new DiagnosticCollector<>();
        List<File> sources;
        try (Stream<Path> s = Files.list(program)) {
            sources = s.filter(f -> f.toString().endsWith(".java")).map(Path::toFile).collect(Collectors.toList());
        }
        try (StandardJavaFileManager files = javac.getStandardFileManager(diagnostics, null, StandardCharsets.UTF_8)) {
            List<String> options = List.of("-classpath", String.join(File.pathSeparator, classPath), "-d", out.toString(),
                    "--release", "17", "-nowarn", "-proc:none");
            boolean ok = javac.getTask(null, files, diagnostics, options, null, files.getJavaFileObjectsFromFiles(sources)).call();
            if (!ok) {
                StringBuilder b = new StringBuilder();
                for (Diagnostic<? extends JavaFileObject> d : diagnostics.getDiagnostics()) {
                    if (d.getKind() == Diagnostic.Kind.ERROR) {
                        b.append(d.getSource() == null ? "" : Path.of(d.getSource().toUri()).getFileName()).append(':')
                                .append(d.getLineNumber()).append(": ").append(d.getMessage(null)).append('\n');
                    }
                }
                fail(program.getFileName() + " does not compile against " + classPath + ":\n" + b);
            }
        }
    }

    /** The directory or jar that holds concord-jade's {@code jade.core.Agent}. */
    private static String compatClasses() {
        for (String e : System.getProperty("java.class.path").split(File.pathSeparator)) {
            if (Files.isRegularFile(Path.of(e, "jade", "core", "Agent.class"))) {
                return e;
            }
        }
        throw new IllegalStateException("concord-jade's classes are not on the test class path");
    }

    /** This test's class path without JADE's jar (which surefire leaves out): concord-jade, Concord, SLF4J. */
    private static String concordClassPath() {
        List<String> l = new ArrayList<>();
        for (String e : System.getProperty("java.class.path").split(File.pathSeparator)) {
            if (!e.contains("ingenias")) {
                l.add(e);
            }
        }
        return String.join(File.pathSeparator, l);
    }

    private static int freePort() {
        return CorpusPorts.freeBase();
    }
}
