package io.concord.layers.authority;

import org.bouncycastle.crypto.params.Ed25519PrivateKeyParameters;
import org.bouncycastle.crypto.signers.Ed25519Signer;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.nio.file.attribute.PosixFilePermission;
import java.nio.file.attribute.PosixFilePermissions;
import java.security.SecureRandom;
import java.util.Base64;
import java.util.HexFormat;
import java.util.List;
import java.util.Set;
import java.util.function.Consumer;

/**
 * An operator's own key (Ed25519): it signs the orders only an operator may give (a held chair's
 * resume), which the ward's agents verify against the {@link Operators} configured for the ward.
 * The platform key makes an agent a member; it does not make anyone an operator.
 *
 * <p>Kept in a text file of mode 0600 that only its owner may read:
 * <pre>
 * # Concord operator key ...
 * operator &lt;64 hex digits: the public key&gt; &lt;name&gt;
 * private &lt;64 hex digits: the Ed25519 seed&gt;
 * </pre>
 * The {@code operator} line alone is what a ward needs ({@link Operators#read}); the file itself may
 * be given to a ward too, which reads only that line. Make one with
 * {@code java -cp concord.jar io.concord.layers.authority.OperatorKey ada.key "nurse Ada"}, or let the
 * demo make one ({@code --operator-key file}).
 */
public final class OperatorKey {
    private static final SecureRandom RANDOM = new SecureRandom();
    private final Operator operator;
    private final Ed25519PrivateKeyParameters key;

    private OperatorKey(String name, Ed25519PrivateKeyParameters key) {
        this.key = key;
        this.operator = new Operator(name, key.generatePublicKey().getEncoded());
    }

    /** A new key for {@code name}, kept in memory only (tests, a console's session). */
    public static OperatorKey generate(String name) {
        return new OperatorKey(name, new Ed25519PrivateKeyParameters(RANDOM));
    }

    /** The operator this key signs as: what a ward configures. */
    public Operator operator() {
        return operator;
    }

    /** The operator's name. */
    public String name() {
        return operator.name();
    }

    /** Signs {@code action} on {@code target} now ({@code atMs}, the signer's epoch milliseconds), with a fresh nonce. */
    public SignedOrder sign(String action, String target, long atMs) {
        byte[] n = new byte[16];
        RANDOM.nextBytes(n);
        String nonce = Base64.getUrlEncoder().withoutPadding().encodeToString(n);
        byte[] data = SignedOrder.signed(action, target, operator.name(), atMs, nonce);
        Ed25519Signer s = new Ed25519Signer();
        s.init(true, key);
        s.update(data, 0, data.length);
        return new SignedOrder(action, target, operator.name(), atMs, nonce,
                Base64.getUrlEncoder().withoutPadding().encodeToString(s.generateSignature()));
    }

    /** Writes this key to a new file of mode 0600; an existing file is never replaced. */
    public void save(Path file) {
        String text = "# Concord operator key of " + operator.name() + ": keep it as a password. A ward needs only the\n"
                + "# 'operator' line (its public key and name); the 'private' line signs this operator's orders.\n"
                + operator.line() + "\nprivate " + HexFormat.of().formatHex(key.getEncoded()) + "\n";
        try {
            Path dir = file.toAbsolutePath().getParent();
            if (dir != null) {
                Files.createDirectories(dir);
            }
            Set<PosixFilePermission> own = PosixFilePermissions.fromString("rw-------");
            try {
                Files.createFile(file, PosixFilePermissions.asFileAttribute(own));
            } catch (UnsupportedOperationException e) {
                Files.createFile(file);
            }
            Files.writeString(file, text, StandardCharsets.UTF_8, StandardOpenOption.TRUNCATE_EXISTING);
        } catch (FileAlreadyExistsException e) {
            throw new IllegalArgumentException("the operator key file " + file + " exists already; it is never written over");
        } catch (IOException e) {
            throw new UncheckedIOException("cannot write the operator key " + file + ": " + e.getMessage(), e);
        }
    }

    /**
     * Reads an operator key file.
     *
     * @throws IllegalArgumentException if it is not one, or others may read it, saying what to do
     */
    public static OperatorKey load(Path file) {
        List<String> lines;
        try {
            lines = Files.readAllLines(file, StandardCharsets.UTF_8);
            try {
                Set<PosixFilePermission> p = Files.getPosixFilePermissions(file);
                if (p.contains(PosixFilePermission.GROUP_READ) || p.contains(PosixFilePermission.OTHERS_READ)) {
                    throw new IllegalArgumentException("the operator key " + file + " may be read by others (mode "
                            + PosixFilePermissions.toString(p) + "); make it the owner's alone: chmod 600 " + file);
                }
            } catch (UnsupportedOperationException e) {
                // not a POSIX file system: nothing to check
            }
        } catch (IOException e) {
            throw new IllegalArgumentException("cannot read the operator key " + file + ": " + e.getMessage(), e);
        }
        Operator op = null;
        byte[] seed = null;
        for (String l : lines) {
            String t = l.strip();
            if (t.startsWith("operator ")) {
                op = Operators.parseLine(t, file.toString());
            } else if (t.startsWith("private ")) {
                try {
                    seed = HexFormat.of().parseHex(t.substring(8).trim());
                } catch (IllegalArgumentException e) {
                    seed = null;
                }
            }
        }
        if (op == null || seed == null || seed.length != 32) {
            throw new IllegalArgumentException(file + " is not an operator key (it needs an 'operator <hex> <name>' line and a 'private "
                    + "<64 hex digits>' line); make one with: java -cp concord.jar io.concord.layers.authority.OperatorKey "
                    + file + " \"your name\"");
        }
        OperatorKey k = new OperatorKey(op.name(), new Ed25519PrivateKeyParameters(seed, 0));
        if (!k.operator.equals(op)) {
            throw new IllegalArgumentException("the operator key " + file + " is damaged: its private key does not match its public key");
        }
        return k;
    }

    /** Reads the key file, or makes one for {@code name} if there is none, saying where ({@code say}). */
    public static OperatorKey loadOrCreate(Path file, String name, Consumer<String> say) {
        if (Files.exists(file)) {
            return load(file);
        }
        OperatorKey k = generate(name);
        k.save(file);
        say.accept("made an operator key for " + name + " in " + file.toAbsolutePath()
                + " (mode 0600; it signs this operator's resumes: keep it as a password)");
        return k;
    }

    /** Makes an operator key: {@code OperatorKey <file> <name>}. */
    public static void main(String[] args) {
        if (args.length != 2) {
            System.err.println("usage: java -cp concord.jar io.concord.layers.authority.OperatorKey <file> \"<operator's name>\"");
            System.exit(2);
        }
        try {
            OperatorKey k = generate(args[1]);
            k.save(Path.of(args[0]));
            System.out.println("made an operator key for " + k.name() + " in " + args[0] + " (mode 0600)");
            System.out.println("give the ward this line (--operators file, or the key file itself):");
            System.out.println(k.operator().line());
        } catch (IllegalArgumentException | UncheckedIOException e) {
            System.err.println(e.getMessage());
            System.exit(2);
        }
    }
}
