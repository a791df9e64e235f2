package jade.content.lang.sl;

/** The symbols of full FIPA-SL, as JADE names them. */
public interface SLVocabulary extends SL2Vocabulary {
}
