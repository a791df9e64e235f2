package io.concord.testkit;

import javax.tools.DiagnosticCollector;
import javax.tools.JavaCompiler;
import javax.tools.JavaFileObject;
import javax.tools.StandardJavaFileManager;
import javax.tools.ToolProvider;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.lang.reflect.InvocationTargetException;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import java.util.function.Predicate;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * The README's examples, as the build keeps them true: every Java block of a Markdown file whose
 * first line is {@code // Name.java} is a whole file, compiled with this JVM's class path and run
 * (its {@code main}), unless that line says it is "compiled by the build" only (it needs hardware).
 * Each module's test takes the examples it has the class path for.
 */
public final class ReadmeExamples {
    /** One example: where its block starts (a line of the file), its class, its source, whether it is run. */
    public record Example(int line, String className, String source, boolean runs) {
        /** Whether its source imports from {@code prefix} (a package's name with its dot). */
        public boolean imports(String prefix) {
            return source.lines().anyMatch(l -> l.strip().startsWith("import " + prefix));
        }
    }

    private static final Pattern FIRST = Pattern.compile("^//\\s*([A-Z][A-Za-z0-9]*)\\.java\\b(.*)$");

    private ReadmeExamples() {
    }

    /** The whole-file examples of {@code markdown}, in order. */
    public static List<Example> of(Path markdown) throws IOException {
        List<String> lines = Files.readAllLines(markdown, StandardCharsets.UTF_8);
        List<Example> out = new ArrayList<>();
        for (int i = 0; i < lines.size(); i++) {
            String fence = lines.get(i).strip();
            if (!fence.startsWith("```java")) {
                continue;
            }
            String indent = lines.get(i).substring(0, lines.get(i).indexOf('`'));
            StringBuilder src = new StringBuilder();
            int j = i + 1;
            for (; j < lines.size() && !lines.get(j).strip().startsWith("```"); j++) {
                String l = lines.get(j);
                src.append(l.startsWith(indent) ? l.substring(indent.length()) : l.strip()).append('\n');
            }
            Matcher m = FIRST.matcher(src.toString().lines().findFirst().orElse(""));
            if (m.matches()) {
                out.add(new Example(i + 1, m.group(1), src.toString(), !m.group(2).contains("compiled by the build")));
            }
            i = j;
        }
        return out;
    }

    /** The examples of {@code markdown} that {@code which} takes. */
    public static List<Example> of(Path markdown, Predicate<Example> which) throws IOException {
        return of(markdown).stream().filter(which).toList();
    }

    /**
     * Compiles the examples into {@code dir} against this JVM's class path.
     *
     * @throws AssertionError with javac's messages, naming the example and its line in the file
     */
    public static void compile(List<Example> examples, Path dir) throws IOException {
        JavaCompiler javac = ToolProvider.getSystemJavaCompiler();
        if (javac == null) {
            throw new AssertionError("no Java compiler in this JVM (a JRE?): the README's examples need a JDK");
        }
        Path src = Files.createDirectories(dir.resolve("src"));
        Path classes = Files.createDirectories(dir.resolve("classes"));
        List<Path> files = new ArrayList<>();
        for (Example e : examples) {
            Path f = src.resolve(e.className() + ".java");
            Files.writeString(f, e.source(), StandardCharsets.UTF_8);
            files.add(f);
        }
        DiagnosticCollector<JavaFileObject> said = new DiagnosticCollector<>();
        try (StandardJavaFileManager fm = javac.getStandardFileManager(said, null, StandardCharsets.UTF_8)) {
            List<String> options = List.of("-d", classes.toString(), "-cp", System.getProperty("java.class.path"), "-proc:none");
            boolean ok = javac.getTask(null, fm, said, options, null, fm.getJavaFileObjectsFromPaths(files)).call();
            if (!ok) {
                StringBuilder why = new StringBuilder("a README example does not compile:");
                said.getDiagnostics().forEach(d -> why.append("\n  ").append(d.getSource() == null ? "" : Path.of(d.getSource().toUri()).getFileName())
                        .append(':').append(d.getLineNumber()).append(": ").append(d.getMessage(null)));
                throw new AssertionError(why.toString());
            }
        }
    }

    /**
     * Runs the example's {@code main} (compiled into {@code dir} by {@link #compile}) in this JVM,
     * for at most {@code timeoutS} seconds; returns what it printed on standard output.
     *
     * @throws AssertionError if it throws or does not end in time
     */
    public static String run(Example e, Path dir, long timeoutS) throws Exception {
        URL[] at = {dir.resolve("classes").toUri().toURL()};
        PrintStream before = System.out;
        ByteArrayOutputStream printed = new ByteArrayOutputStream();
        try (URLClassLoader loader = new URLClassLoader(at, ReadmeExamples.class.getClassLoader())) {
            var main = loader.loadClass(e.className()).getMethod("main", String[].class);
            System.setOut(new PrintStream(new TeeStream(printed, before), true, StandardCharsets.UTF_8));
            CompletableFuture<Void> done = CompletableFuture.runAsync(() -> {
                // As a program of its own: its classes are its thread's (JADE's createNewAgent looks there).
                ClassLoader was = Thread.currentThread().getContextClassLoader();
                Thread.currentThread().setContextClassLoader(loader);
                try {
                    main.invoke(null, (Object) new String[0]);
                } catch (InvocationTargetException x) {
                    throw new AssertionError(e.className() + " (README line " + e.line() + ") threw " + x.getCause(), x.getCause());
                } catch (IllegalAccessException x) {
                    throw new AssertionError(e.className() + ": its main is not public", x);
                } finally {
                    Thread.currentThread().setContextClassLoader(was);
                }
            });
            done.get(timeoutS, TimeUnit.SECONDS);
        } catch (java.util.concurrent.TimeoutException x) {
            throw new AssertionError(e.className() + " (README line " + e.line() + ") did not end within " + timeoutS + " s");
        } catch (java.util.concurrent.ExecutionException x) {
            throw x.getCause() instanceof AssertionError a ? a : new AssertionError(x.getCause());
        } finally {
            System.setOut(before);
        }
        return printed.toString(StandardCharsets.UTF_8);
    }

    /** Writes to both: what an example prints is kept and still shown. */
    private static final class TeeStream extends java.io.OutputStream {
        private final java.io.OutputStream a;
        private final java.io.OutputStream b;

        TeeStream(java.io.OutputStream a, java.io.OutputStream b) {
            this.a = a;
            this.b = b;
        }

        @Override
        public synchronized void write(int c) throws IOException {
            a.write(c);
            b.write(c);
        }

        @Override
        public synchronized void write(byte[] buf, int off, int len) throws IOException {
            a.write(buf, off, len);
            b.write(buf, off, len);
        }
    }
}
