package io.concord.bench;

import org.openjdk.jmh.results.RunResult;
import org.openjdk.jmh.runner.Runner;
import org.openjdk.jmh.runner.RunnerException;
import org.openjdk.jmh.runner.options.ChainedOptionsBuilder;
import org.openjdk.jmh.runner.options.OptionsBuilder;
import org.openjdk.jmh.runner.options.TimeValue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.LocalDate;
import java.util.ArrayList;
import java.util.Collection;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.TimeUnit;

/**
 * {@code bench/run quick|full [name ...]}: runs the named benchmarks, prints one RESULT line per
 * measured point and writes the report under {@code bench/report/}. Names available now:
 * {@code stack}. The others of the benchmarks issue come with their issues.
 */
public final class BenchMain {
    private BenchMain() {
    }

    public static void main(String[] args) throws RunnerException, IOException {
        boolean full = args.length > 0 && args[0].equals("full");
        List<String> names = new ArrayList<>();
        for (int i = args.length > 0 && (args[0].equals("quick") || args[0].equals("full")) ? 1 : 0; i < args.length; i++) {
            names.add(args[i]);
        }
        if (names.isEmpty()) {
            names.add("stack");
        }
        Path reportDir = Path.of(System.getProperty("concord.report", "bench/report"));
        Files.createDirectories(reportDir);
        for (String name : names) {
            switch (name) {
                case "stack" -> stack(full, reportDir);
                default -> {
                    System.err.println("unknown benchmark '" + name + "'; available: stack");
                    System.exit(2);
                }
            }
        }
    }

    private static void stack(boolean full, Path reportDir) throws RunnerException, IOException {
        ChainedOptionsBuilder opts = new OptionsBuilder()
                .include(StackBenchmark.class.getSimpleName())
                .mode(org.openjdk.jmh.annotations.Mode.SampleTime)
                .timeUnit(TimeUnit.MICROSECONDS)
                .forks(1)
                .warmupIterations(full ? 5 : 3).warmupTime(TimeValue.seconds(full ? 5 : 2))
                .measurementIterations(full ? 10 : 3).measurementTime(TimeValue.seconds(full ? 5 : 2));
        Collection<RunResult> results = new Runner(opts.build()).run();
        StringBuilder table = new StringBuilder();
        table.append("# Stack: one message down one stack and up another\n\n")
                .append("500-byte content, no sockets, both copies of each frame delivered; JMH sample time, ")
                .append(full ? "full" : "quick").append(" mode, ").append(LocalDate.now()).append(".\n\n")
                .append(Machine.describe()).append("\n\n")
                .append("| profile | median µs | p90 µs | p99 µs | samples |\n|---|---|---|---|---|\n");
        for (RunResult r : results) {
            String profile = r.getParams().getParam("profile");
            var stats = r.getPrimaryResult().getStatistics();
            double median = stats.getPercentile(50);
            System.out.printf(Locale.ROOT, "RESULT stack %s 500 down_up_us=%.2f%n",
                    profile.equals("CLASS_7") ? "class7" : profile.toLowerCase(Locale.ROOT), median);
            table.append(String.format(Locale.ROOT, "| %s | %.2f | %.2f | %.2f | %d |%n", profile, median,
                    stats.getPercentile(90), stats.getPercentile(99), stats.getN()));
        }
        table.append("\nFor scale: a 500-byte UDP send and receive on loopback costs about 5 µs of system calls ")
                .append("on these machines (ARCHITECTURE.md); `bench/run quick udp` will measure it in the same run.\n");
        Files.writeString(reportDir.resolve("stack.md"), table.toString());
    }
}
