package io.concord.jadecompat;

import com.tngtech.archunit.core.domain.JavaClass;
import com.tngtech.archunit.core.domain.JavaClasses;
import com.tngtech.archunit.core.domain.JavaCodeUnit;
import com.tngtech.archunit.core.domain.JavaField;
import com.tngtech.archunit.core.domain.JavaMember;
import com.tngtech.archunit.core.domain.JavaModifier;
import com.tngtech.archunit.core.importer.ClassFileImporter;
import org.junit.jupiter.api.Test;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.TreeMap;
import java.util.TreeSet;
import java.util.jar.JarFile;
import java.util.stream.Collectors;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * Every public class, and every public or protected constructor, method and field, of JADE 4.3's
 * jar that concord-jade lacks, read from both sets of class files (JADE's jar is read as files,
 * never loaded). The list is written to {@code target/API-GAPS.md} and must equal the committed
 * {@code jade-compat/API-GAPS.md}: a gap the committed list does not name fails the test (the
 * README's "Not supported yet" points to that list, so it never claims less than the jar lacks),
 * and so does a named gap that is filled (take it off). {@code cp target/API-GAPS.md API-GAPS.md}
 * after a change, and read the diff.
 *
 * <p>Entries: a package concord-jade has no class of ({@code package jade.imtp.leap (39 classes)});
 * a class missing from a package concord-jade has; a member missing from a class it has (also when
 * it is there but less visible than JADE's). Members are compared by name and erased parameter
 * types (return types are not compared); inherited members count on concord-jade's side.
 */
class ApiGapsTest {
    static final Path COMMITTED = Path.of("API-GAPS.md");
    static final Path GENERATED = Path.of("target", "API-GAPS.md");

    @Test
    void theCommittedListNamesEveryGapBetweenJadesJarAndConcordJade() throws Exception {
        Path jar = Path.of(System.getProperty("jade.jar"));
        assertTrue(Files.isRegularFile(jar), "JADE's jar is not at " + jar);
        JavaClasses jade;
        try (JarFile j = new JarFile(jar.toFile())) {
            jade = new ClassFileImporter().importJar(j);
        }
        Path compatDir = Path.of(jade.core.Agent.class.getProtectionDomain().getCodeSource().getLocation().toURI());
        JavaClasses ours = new ClassFileImporter().importPath(compatDir);

        Gaps gaps = gaps(jade, ours);
        assertTrue(gaps.jadeClasses > 800, "read only " + gaps.jadeClasses + " public classes from JADE's jar");
        String text = render(gaps);
        Files.createDirectories(GENERATED.getParent());
        Files.writeString(GENERATED, text, StandardCharsets.UTF_8);
        System.out.println("API gaps: " + gaps.entries.size() + " entries (" + gaps.missingClasses + " classes, "
                + gaps.missingMembers + " members of classes concord-jade has) of JADE's " + gaps.jadeClasses
                + " public classes and " + gaps.jadeMembers + " members; written to " + GENERATED.toAbsolutePath());

        Set<String> committed = Files.isRegularFile(COMMITTED) ? entries(Files.readString(COMMITTED)) : Set.of();
        Set<String> unnamed = new TreeSet<>(gaps.entries.keySet());
        unnamed.removeAll(committed);
        Set<String> filled = new TreeSet<>(committed);
        filled.removeAll(gaps.entries.keySet());
        assertEquals(Set.of(), unnamed, "concord-jade lacks these and " + COMMITTED + " does not say so "
                + "(cp " + GENERATED + " " + COMMITTED + ", and say so in the README if it matters)");
        assertEquals(Set.of(), filled, COMMITTED + " names these as missing, but concord-jade has them now: take them off "
                + "(cp " + GENERATED + " " + COMMITTED + ")");
    }

    /** The entries of a list: the text between the first pair of backticks of each {@code - } line. */
    static Set<String> entries(String md) {
        Set<String> s = new TreeSet<>();
        for (String line : md.split("\n")) {
            if (line.startsWith("- `")) {
                int end = line.indexOf('`', 3);
                s.add(line.substring(3, end));
            }
        }
        return s;
    }

    static final class Gaps {
        /** Entry to the note shown after it (how many classes a package holds). */
        final Map<String, String> entries = new TreeMap<>();
        int jadeClasses;
        int jadeMembers;
        int missingClasses;
        int missingMembers;
    }

    static Gaps gaps(JavaClasses jade, JavaClasses ours) {
        Gaps g = new Gaps();
        Set<String> ourPackages = new TreeSet<>();
        for (JavaClass c : ours) {
            ourPackages.add(c.getPackageName());
        }
        Map<String, Integer> absentPackages = new TreeMap<>();
        List<JavaClass> sorted = new ArrayList<>();
        jade.forEach(sorted::add);
        sorted.sort((a, b) -> a.getName().compareTo(b.getName()));
        for (JavaClass c : sorted) {
            if (!visible(c)) {
                continue;
            }
            g.jadeClasses++;
            List<JavaMember> members = members(c);
            g.jadeMembers += members.size();
            if (!ourPackages.contains(c.getPackageName())) {
                absentPackages.merge(c.getPackageName().isEmpty() ? "(default)" : c.getPackageName(), 1, Integer::sum);
                g.missingClasses++;
                continue;
            }
            Optional<JavaClass> mine = ours.contain(c.getName()) ? Optional.of(ours.get(c.getName())) : Optional.empty();
            if (mine.isEmpty() || !visible(mine.get())) {
                g.entries.put("class " + c.getName(), "");
                g.missingClasses++;
                continue;
            }
            for (JavaMember m : members) {
                if (!has(mine.get(), m)) {
                    g.entries.put(signature(c, m), "");
                    g.missingMembers++;
                }
            }
        }
        absentPackages.forEach((p, n) -> g.entries.put("package " + p, " (" + n + (n == 1 ? " public class)" : " public classes)")));
        return g;
    }

    private static boolean visible(JavaClass c) {
        if (c.isAnonymousClass() || c.isLocalClass() || !c.getModifiers().contains(JavaModifier.PUBLIC)) {
            return false;
        }
        return c.getEnclosingClass().map(ApiGapsTest::visible).orElse(true);
    }

    private static boolean userVisible(JavaMember m) {
        Set<JavaModifier> mods = m.getModifiers();
        return (mods.contains(JavaModifier.PUBLIC) || mods.contains(JavaModifier.PROTECTED))
                && !mods.contains(JavaModifier.SYNTHETIC) && !mods.contains(JavaModifier.BRIDGE);
    }

    private static List<JavaMember> members(JavaClass c) {
        List<JavaMember> l = new ArrayList<>();
        for (JavaMember m : c.getMembers()) {
            if (userVisible(m) && !m.getName().equals("<clinit>")) {
                // An enum's values()/valueOf() and a record's accessors come with the kind of class.
                l.add(m);
            }
        }
        return l;
    }

    private static String params(JavaCodeUnit u) {
        return u.getRawParameterTypes().stream().map(JavaClass::getName).collect(Collectors.joining(","));
    }

    static String signature(JavaClass c, JavaMember m) {
        if (m instanceof JavaField) {
            return "field " + c.getName() + "." + m.getName();
        }
        JavaCodeUnit u = (JavaCodeUnit) m;
        String kind = m.getName().equals("<init>") ? "constructor " + c.getName() : "method " + c.getName() + "." + m.getName();
        return kind + "(" + params(u) + ")";
    }

    /** Whether {@code mine} has (declares or inherits) a member as visible as JADE's {@code m}. */
    private static boolean has(JavaClass mine, JavaMember m) {
        boolean jadePublic = m.getModifiers().contains(JavaModifier.PUBLIC);
        Set<? extends JavaMember> candidates;
        if (m instanceof JavaField) {
            candidates = mine.getAllFields();
        } else if (m.getName().equals("<init>")) {
            candidates = mine.getConstructors();
        } else {
            candidates = mine.getAllMethods();
        }
        for (JavaMember o : candidates) {
            if (!o.getName().equals(m.getName())) {
                continue;
            }
            if (m instanceof JavaCodeUnit && !params((JavaCodeUnit) o).equals(params((JavaCodeUnit) m))) {
                continue;
            }
            Set<JavaModifier> mods = o.getModifiers();
            if (mods.contains(JavaModifier.PUBLIC) || !jadePublic && mods.contains(JavaModifier.PROTECTED)) {
                return true;
            }
        }
        return false;
    }

    static String render(Gaps g) {
        StringBuilder b = new StringBuilder();
        b.append("# What concord-jade lacks of JADE 4.3's jar\n\n")
                .append("Generated by `ApiGapsTest` (it writes `target/API-GAPS.md` and fails when this list and concord-jade differ):\n")
                .append("every public class, and every public or protected constructor, method and field, of JADE 4.3's jar\n")
                .append("that concord-jade does not have. A package concord-jade has no class of is one entry; a class missing\n")
                .append("from a package it has is one entry; so is a member missing from a class it has (or there but less\n")
                .append("visible than JADE's). Members are matched by name and parameter types. The README's \"Not supported yet\"\n")
                .append("says what matters most of this; this list is all of it.\n\n")
                .append(g.entries.size()).append(" entries: ").append(g.missingClasses).append(" of JADE's ").append(g.jadeClasses)
                .append(" public classes, and ").append(g.missingMembers).append(" members of the classes concord-jade has.\n\n");
        for (Map.Entry<String, String> e : g.entries.entrySet()) {
            b.append("- `").append(e.getKey()).append('`').append(e.getValue()).append('\n');
        }
        return b.toString();
    }

    @Test
    void theListReaderTakesEachEntryAndNothingElse() throws IOException {
        assertEquals(Set.of("package jade.imtp.leap", "method jade.core.Agent.doMove(jade.core.Location)"),
                entries("# title\n\ntext `not this`\n- `package jade.imtp.leap` (39 public classes)\n"
                        + "- `method jade.core.Agent.doMove(jade.core.Location)`\n  - `nested, not an entry`\n"));
    }
}
