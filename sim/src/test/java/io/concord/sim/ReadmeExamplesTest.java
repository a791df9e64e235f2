package io.concord.sim;

import io.concord.testkit.ReadmeExamples;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.nio.file.Path;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The README's and the docs' whole-file examples (a Java block whose first line is {@code // Name.java})
 * that need Concord's own modules: compiled as they are printed, and run, each saying what the README
 * says it does. The JADE-API example runs in jade-compat's test, the gateway's in jade-bridge's.
 */
class ReadmeExamplesTest {
    static final Path README = Path.of("..", "README.md");

    @Test
    void theReadmesExamplesCompileAndRun(@TempDir Path dir) throws Exception {
        List<ReadmeExamples.Example> mine = new java.util.ArrayList<>(ReadmeExamples.of(README, e -> !e.imports("jade.") && !e.imports("io.concord.jade.")));
        // And the docs' own: the content language's and the map generator's.
        mine.addAll(ReadmeExamples.of(Path.of("..", "docs", "content.md")));
        mine.addAll(ReadmeExamples.of(Path.of("..", "docs", "hospital-map.md")));
        assertTrue(mine.stream().map(ReadmeExamples.Example::className).toList()
                        .containsAll(List.of("Hello", "Shop", "Stacks", "World", "Ward", "RealChair", "Replay", "Books", "Generated")),
                "the README's examples: " + mine.stream().map(ReadmeExamples.Example::className).toList());
        ReadmeExamples.compile(mine, dir);
        for (ReadmeExamples.Example e : mine) {
            if (!e.runs()) {
                continue;
            }
            String printed = ReadmeExamples.run(e, dir, 120);
            String expected = switch (e.className()) {
                case "Hello" -> "echo hello";
                case "Shop" -> "Dune at 42 (1 seller; container seller1@shop)";
                case "Stacks" -> "logger@";
                case "World" -> "chair1 drove ";
                case "Ward" -> "done by control-chair1";
                case "Books" -> "((action (agent-identifier :name me@P) (Sell :book (Book :authors (sequence Ann) :price 9.5 :title X))))\n"
                        + "missing mandatory slot :title of Book";
                case "Generated" -> " parking places";
                case "Replay" -> {
                    // The trace's hash, the same on a second run: the README's promise.
                    String again = ReadmeExamples.run(e, dir, 120);
                    assertTrue(printed.strip().matches("-?\\d+") && printed.equals(again), "Replay printed " + printed + " then " + again);
                    yield printed.strip();
                }
                default -> throw new AssertionError("an example this test does not know: " + e.className() + "; say what it prints");
            };
            assertTrue(printed.contains(expected), e.className() + " (README line " + e.line() + ") printed:\n" + printed);
        }
    }
}
