package io.concord.core;

import com.tngtech.archunit.core.domain.JavaClass;
import com.tngtech.archunit.core.domain.JavaClasses;
import com.tngtech.archunit.core.domain.JavaCodeUnit;
import com.tngtech.archunit.core.domain.JavaField;
import com.tngtech.archunit.core.domain.JavaModifier;
import com.tngtech.archunit.core.importer.ClassFileImporter;
import com.tngtech.archunit.library.dependencies.SliceAssignment;
import com.tngtech.archunit.library.dependencies.SliceIdentifier;

import org.junit.jupiter.api.Test;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;

import static com.tngtech.archunit.lang.syntax.ArchRuleDefinition.noClasses;
import static com.tngtech.archunit.library.dependencies.SlicesRuleDefinition.slices;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The architecture every module's main code keeps. Each module's {@code ArchitectureTest} extends
 * this class (in core's test jar, so the rules and their tests are written once) and so runs the
 * first two rules on its own {@code target/classes}.
 *
 * <ul>
 * <li>No cycle between packages: each depends only on those below it, so each can be read, tested
 * and changed from the bottom up. An {@code internal} package is its parent's implementation
 * (public only so that Concord's other modules can reach it), so it counts as part of its parent:
 * {@code io.concord.core.net.internal} is in the slice {@code core.net}.</li>
 * <li>Internals stay inside: no public or protected member of a public type outside the
 * {@code internal} packages names a type of one (as a field, a parameter, a return type), so a
 * user of the API never needs one.</li>
 * <li>A user's code ({@code examples}) uses no internal type.</li>
 * </ul>
 */
public class ArchitectureRules {

    /** This module's main classes, read once for its tests. */
    protected final JavaClasses main = mainClasses();

    @Test
    void mainCodeHasNoPackageCycle() {
        noPackageCycles(main);
    }

    @Test
    void theApiNamesNoInternalType() {
        internalsStayInside(main);
    }

    /** The main classes of the module whose tests run: its {@code target/classes}. */
    public static JavaClasses mainClasses() {
        JavaClasses main = new ClassFileImporter().importPath(Path.of("target", "classes"));
        assertFalse(main.isEmpty(), "no main classes under target/classes");
        return main;
    }

    /** Fails, naming the classes whose dependencies close it, on any cycle between packages. */
    public static void noPackageCycles(JavaClasses main) {
        slices().assignedFrom(PACKAGES_WITH_THEIR_INTERNALS).should().beFreeOfCycles().check(main);
    }

    /** Fails, naming each member, where the API names a type of an internal package. */
    public static void internalsStayInside(JavaClasses main) {
        List<String> leaks = new ArrayList<>();
        for (JavaClass c : main) {
            if (internal(c) || !c.getModifiers().contains(JavaModifier.PUBLIC)) {
                continue;
            }
            for (JavaField f : c.getFields()) {
                if (api(f.getModifiers()) && internal(f.getRawType())) {
                    leaks.add(f.getFullName() + " is of type " + f.getRawType().getName());
                }
            }
            for (JavaCodeUnit u : c.getCodeUnits()) {
                if (!api(u.getModifiers()) || u.getModifiers().contains(JavaModifier.SYNTHETIC)) {
                    continue;
                }
                if (internal(u.getRawReturnType())) {
                    leaks.add(u.getFullName() + " returns " + u.getRawReturnType().getName());
                }
                for (JavaClass p : u.getRawParameterTypes()) {
                    if (internal(p)) {
                        leaks.add(u.getFullName() + " takes " + p.getName());
                    }
                }
            }
        }
        assertTrue(leaks.isEmpty(), "the API names internal types (make the member package-private, or the type API): " + leaks);
    }

    /** Fails on any dependency of these classes on a type of an internal package. */
    public static void usesNoInternals(JavaClasses main) {
        noClasses().should().dependOnClassesThat().resideInAPackage("..internal..")
                .because("internal packages are Concord's own, not an API: they change without notice")
                .check(main);
    }

    private static boolean api(Set<JavaModifier> m) {
        return m.contains(JavaModifier.PUBLIC) || m.contains(JavaModifier.PROTECTED);
    }

    private static boolean internal(JavaClass c) {
        JavaClass base = c.isArray() ? c.getBaseComponentType() : c;
        return base.getPackageName().contains(".internal");
    }

    /** A package's slice: its name after {@code io.concord.}, with a trailing {@code .internal...} cut off. */
    private static final SliceAssignment PACKAGES_WITH_THEIR_INTERNALS = new SliceAssignment() {
        @Override
        public SliceIdentifier getIdentifierOf(JavaClass c) {
            String p = c.getPackageName();
            if (!p.startsWith("io.concord.")) {
                return SliceIdentifier.ignore();
            }
            int i = p.indexOf(".internal");
            return SliceIdentifier.of(i < 0 ? p.substring("io.concord.".length()) : p.substring("io.concord.".length(), i));
        }

        @Override
        public String getDescription() {
            return "packages of io.concord, each with its internal packages";
        }
    };
}
