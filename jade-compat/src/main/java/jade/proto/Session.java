package jade.proto;

import jade.core.AID;

/** One receiver's conversation inside an initiator: where it stands. */
final class Session {
    static final int SENT = 0;
    static final int RESPONDED = 1;
    static final int DONE = 2;

    final String key;
    final AID receiver;
    int state = SENT;

    Session(String key, AID receiver) {
        this.key = key;
        this.receiver = receiver;
    }
}
