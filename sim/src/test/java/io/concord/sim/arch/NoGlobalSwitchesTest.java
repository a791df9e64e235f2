package io.concord.sim.arch;

import org.junit.jupiter.api.Test;

import java.io.File;
import java.lang.reflect.Field;
import java.lang.reflect.Modifier;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.jar.JarFile;
import java.util.stream.Stream;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * No production class of Concord has a public static field that is not final: no code on the
 * class path can switch a defence off, or change a running platform's behaviour, behind the back
 * of the stacks that were built (the threat tests build stacks without a defence instead:
 * {@code SafetyStack.Builder#withoutDefences}).
 */
class NoGlobalSwitchesTest {

    @Test
    void noProductionClassHasAPublicStaticFieldThatCanBeChanged() throws Exception {
        List<String> classes = new ArrayList<>();
        for (String entry : System.getProperty("java.class.path").split(File.pathSeparator)) {
            Path p = Path.of(entry);
            if (entry.contains("test-classes")) {
                continue;
            }
            if (Files.isDirectory(p) && Files.isDirectory(p.resolve("io/concord"))) {
                try (Stream<Path> s = Files.walk(p.resolve("io/concord"))) {
                    s.filter(f -> f.toString().endsWith(".class")).forEach(f -> classes.add(name(p.relativize(f).toString())));
                }
            } else if (entry.endsWith(".jar") && p.getFileName().toString().startsWith("concord-") && !entry.endsWith("-tests.jar")) {
                try (JarFile jar = new JarFile(entry)) {
                    jar.stream().filter(e -> e.getName().startsWith("io/concord/") && e.getName().endsWith(".class"))
                            .forEach(e -> classes.add(name(e.getName())));
                }
            }
        }
        assertTrue(classes.size() > 200, "Concord's classes were found on the class path: " + classes.size());
        List<String> switches = new ArrayList<>();
        for (String c : classes) {
            Field[] fields;
            try {
                fields = Class.forName(c, false, getClass().getClassLoader()).getDeclaredFields();
            } catch (ClassNotFoundException | LinkageError e) {
                continue;   // a class whose optional dependency is not on this class path
            }
            for (Field f : fields) {
                int m = f.getModifiers();
                if (Modifier.isPublic(m) && Modifier.isStatic(m) && !Modifier.isFinal(m)) {
                    switches.add(c + "." + f.getName());
                }
            }
        }
        assertEquals(List.of(), switches, "public static fields any code could change");
    }

    private static String name(String file) {
        return file.replace(File.separatorChar, '/').replace('/', '.').substring(0, file.length() - ".class".length());
    }
}
