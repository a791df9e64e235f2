package io.concord.jade;

import io.concord.testkit.ReadmeExamples;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.nio.file.Path;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** The README's gateway example (a platform serving FIPA's HTTP MTP), compiled as printed and run. */
class ReadmeExampleTest {
    @Test
    void theReadmesGatewayExampleCompilesAndRuns(@TempDir Path dir) throws Exception {
        List<ReadmeExamples.Example> gateway = ReadmeExamples.of(Path.of("..", "README.md"), e -> e.imports("io.concord.jade."));
        assertEquals(List.of("Gateway"), gateway.stream().map(ReadmeExamples.Example::className).toList());
        ReadmeExamples.compile(gateway, dir);
        String printed = ReadmeExamples.run(gateway.get(0), dir, 60);
        assertTrue(printed.contains("JADE agents reach seller1@concord at http://127.0.0.1:7779/acc"), printed);
    }
}
