package io.concord.jadecompat;

import io.concord.testkit.ReadmeExamples;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.nio.file.Path;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** The README's JADE-API example (its Profile and main container), compiled as printed against concord-jade and run. */
class ReadmeExampleTest {
    @Test
    void theReadmesJadeExampleCompilesAndRunsOnConcord(@TempDir Path dir) throws Exception {
        List<ReadmeExamples.Example> jade = ReadmeExamples.of(Path.of("..", "README.md"), e -> e.imports("jade."));
        assertEquals(List.of("JadeShop"), jade.stream().map(ReadmeExamples.Example::className).toList());
        ReadmeExamples.compile(jade, dir);
        String printed = ReadmeExamples.run(jade.get(0), dir, 60);
        assertTrue(printed.contains("seller sells Dune=30"), printed);
    }
}
