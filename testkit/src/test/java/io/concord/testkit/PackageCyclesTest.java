package io.concord.testkit;

import com.tngtech.archunit.core.domain.JavaClasses;
import com.tngtech.archunit.core.importer.ClassFileImporter;
import org.junit.jupiter.api.Test;

import java.nio.file.Path;

import static com.tngtech.archunit.library.dependencies.SlicesRuleDefinition.slices;
import static org.junit.jupiter.api.Assertions.assertFalse;

/**
 * This module's main code has no cycle between its packages: each package depends only on those
 * below it, so each can be read, tested and changed from the bottom up. A cycle fails the build
 * here, naming the classes whose dependencies close it. (Every module has this test.)
 */
class PackageCyclesTest {

    @Test
    void mainCodeHasNoPackageCycle() {
        JavaClasses main = new ClassFileImporter().importPath(Path.of("target", "classes"));
        assertFalse(main.isEmpty(), "no main classes under target/classes");
        slices().matching("io.concord.(**)").should().beFreeOfCycles().check(main);
    }
}
