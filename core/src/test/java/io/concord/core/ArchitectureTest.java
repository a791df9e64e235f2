package io.concord.core;

import org.junit.jupiter.api.Test;

import java.io.IOException;
import java.io.InputStream;
import java.lang.module.ModuleDescriptor;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.function.Function;
import java.util.stream.Collectors;

import static org.junit.jupiter.api.Assertions.assertEquals;

/**
 * This module's main code keeps the architecture ({@link ArchitectureRules}); and core's module
 * descriptor keeps its internal packages to Concord's modules.
 */
class ArchitectureTest extends ArchitectureRules {

    /**
     * Core's module descriptor exports every API package to everyone and each internal package only
     * to Concord's own modules, so that on the module path an application cannot reach them.
     */
    @Test
    void theModuleExportsTheApiAndLendsTheInternalsOnlyToConcord() throws IOException {
        ModuleDescriptor d;
        try (InputStream in = Files.newInputStream(Path.of("target", "classes", "module-info.class"))) {
            d = ModuleDescriptor.read(in);
        }
        Map<String, ModuleDescriptor.Exports> exports = d.exports().stream()
                .collect(Collectors.toMap(ModuleDescriptor.Exports::source, Function.identity()));
        Map<String, String> wrong = new TreeMap<>();
        main.stream().map(c -> c.getPackageName()).filter(p -> p.startsWith("io.concord.")).distinct().forEach(p -> {
            ModuleDescriptor.Exports e = exports.get(p);
            if (p.contains(".internal")) {
                if (e == null || !e.isQualified() || !e.targets().stream().allMatch(t -> t.startsWith("io.concord."))) {
                    wrong.put(p, "an internal package must be exported only to Concord's modules, is " + e);
                }
            } else if (e == null || e.isQualified()) {
                wrong.put(p, "an API package must be exported to everyone, is " + e);
            }
        });
        assertEquals(Map.of(), wrong);
        assertEquals(Set.of("io.concord.core.layer.StackProvider"), d.uses(),
                "the runtime finds the safety stack with ServiceLoader, which a named module must declare");
    }
}
