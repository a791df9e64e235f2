package io.concord.layers;

import com.tngtech.archunit.core.domain.JavaClasses;
import io.concord.core.ArchitectureRules;
import org.junit.jupiter.api.Test;

/**
 * This module's main code keeps the architecture (io.concord.core.ArchitectureRules): no cycle
 * between its packages, and no type of an internal package in its API. Every module has this test.
 */
class ArchitectureTest {

    private final JavaClasses main = ArchitectureRules.mainClasses();

    @Test
    void mainCodeHasNoPackageCycle() {
        ArchitectureRules.noPackageCycles(main);
    }

    @Test
    void theApiNamesNoInternalType() {
        ArchitectureRules.internalsStayInside(main);
    }
}
